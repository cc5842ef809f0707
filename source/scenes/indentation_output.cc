#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <optional>
#include <sstream>

#include <ssc/scenes/indentation_output.h>

namespace ssc
{
  namespace
  {
    /// The x range of the section (and of the surface profile).
    std::pair<double, double>
    section_range(const Parameters &parameters)
    {
      const double L = std::min(parameters.punch.profile_length,
                                parameters.mesh.patch_length_x);
      // a quarter model holds x >= 0 only
      return {parameters.mesh.symmetry == MeshSymmetry::quarter ? 0. : -L / 2,
              L / 2};
    }


    /// Where the triangle @p t crosses the plane y = 0: a segment, or
    /// nothing (vertices on the plane count as y > 0, so that a triangle
    /// touching it adds no zero-length segment).
    std::optional<std::array<Point<3>, 2>>
    cut_by_section(const std::array<Point<3>, 3> &t)
    {
      std::vector<Point<3>> ends;
      for (unsigned int e = 0; e < 3; ++e)
        {
          const Point<3> &a = t[e], &b = t[(e + 1) % 3];
          if ((a[1] < 0) != (b[1] < 0))
            ends.push_back(a + (b - a) * (a[1] / (a[1] - b[1])));
        }
      if (ends.size() != 2)
        return std::nullopt;
      return std::array<Point<3>, 2>{{ends[0], ends[1]}};
    }
  } // namespace


  std::vector<Point<3>>
  profile_points(const PunchParameters &punch,
                 const double           patch_length,
                 const bool             from_centre)
  {
    const double          L     = std::min(punch.profile_length, patch_length);
    const unsigned int    n     = punch.profile_points;
    const double          start = from_centre ? 0. : -L / 2;
    const double          span  = from_centre ? L / 2 : L;
    std::vector<Point<3>> points;
    for (unsigned int i = 0; i < n; ++i)
      points.emplace_back(start + span * i / (n - 1), 0., 0.);
    return points;
  }


  std::vector<double>
  vertical_displacements(const std::vector<PointLocation> &locations,
                         const DisplacementField          &field)
  {
    std::vector<Tensor<1, 3>> u;
    std::vector<Tensor<2, 3>> gradient;
    field.evaluate_at(locations, u, gradient);
    std::vector<double> uz(u.size());
    for (unsigned int i = 0; i < u.size(); ++i)
      uz[i] = u[i][2];
    return uz;
  }


  CentreAxisStrains::CentreAxisStrains(const LayerStack   &stack,
                                       const PointLocator &locator)
  {
    for (unsigned int k = 0; k <= stack.n_layers(); ++k)
      interfaces.emplace_back(0, 0, -stack.depth_of_interface(k, 0, 0));
    locations = locator.locate(interfaces);
  }


  std::vector<double>
  CentreAxisStrains::evaluate(const DisplacementField &field) const
  {
    const std::vector<double> uz = vertical_displacements(locations, field);
    std::vector<double>       strains;
    for (unsigned int l = 0; l + 1 < interfaces.size(); ++l)
      strains.push_back((uz[l + 1] - uz[l]) /
                        (interfaces[l][2] - interfaces[l + 1][2]));
    return strains;
  }


  void
  write_surface_profile(const PunchParameters                  &punch,
                        const std::vector<Point<3>>            &points,
                        const std::vector<double>              &loads,
                        const std::vector<std::vector<double>> &profiles,
                        RunOutput                              &output)
  {
    std::ostringstream csv;
    csv << "x_mm";
    for (const double load : loads)
      csv << (punch.control == PunchControl::force ? ",uz_mm_at_F" :
                                                     ",uz_mm_at_depth")
          << load;
    csv << '\n' << std::setprecision(8);
    for (unsigned int i = 0; i < points.size(); ++i)
      {
        csv << points[i][0];
        for (const auto &profile : profiles)
          csv << ',' << profile[i];
        csv << '\n';
      }
    output.write_text("surface_profile.csv", csv.str());
  }


  void
  write_section(const Parameters        &parameters,
                const PointLocator      &locator,
                const DisplacementField &field,
                const LayerMaterials    &materials,
                RunOutput               &output)
  {
    const LayerStack &layers  = parameters.layers;
    const auto [x_min, x_max] = section_range(parameters);
    const unsigned int    nx = 121, nz = 81;
    std::vector<Point<3>> points;
    for (unsigned int i = 0; i < nx; ++i)
      {
        const double x = x_min + (x_max - x_min) * i / (nx - 1);
        const double bottom =
          layers.depth_of_interface(layers.n_layers(), x, 0.);
        for (unsigned int k = 0; k < nz; ++k)
          points.emplace_back(x, 0., -bottom * k / (nz - 1));
      }
    std::vector<Tensor<1, 3>> u;
    std::vector<Tensor<2, 3>> gradient;
    field.evaluate_at(locator.locate(points), u, gradient);
    std::ostringstream csv;
    csv << "x_mm,z_mm,layer,ux_mm,uz_mm,von_mises_kPa\n"
        << std::setprecision(7);
    for (unsigned int k = 0; k < points.size(); ++k)
      {
        const unsigned int l   = layers.layer_at(points[k]);
        const Material    &law = materials[l];
        const Tensor<2, 3> F   = unit_symmetric_tensor<3>() + gradient[k];
        const double       mises =
          law.kinematics() == Kinematics::small_strain || determinant(F) > 0 ?
                  von_mises(law.cauchy_stress(points[k], F)) :
                  std::numeric_limits<double>::quiet_NaN();
        csv << points[k][0] << ',' << points[k][2] << ',' << l << ',' << u[k][0]
            << ',' << u[k][2] << ',' << 1e3 * mises << '\n';
      }
    output.write_text("section.csv", csv.str());
  }



  void
  write_septa_section(const Parameters        &parameters,
                      const Microstructure    &microstructure,
                      const PointLocator      &locator,
                      const DisplacementField &field,
                      RunOutput               &output)
  {
    const auto [x_min, x_max] = section_range(parameters);
    std::vector<Point<3>>     ends;
    std::vector<unsigned int> layers;
    for (const Septum &septum : microstructure.septa())
      for (const auto &triangle : septum.triangles)
        if (const auto segment = cut_by_section(triangle))
          if (std::min((*segment)[0][0], (*segment)[1][0]) >= x_min &&
              std::max((*segment)[0][0], (*segment)[1][0]) <= x_max)
            {
              ends.insert(ends.end(), segment->begin(), segment->end());
              layers.push_back(septum.layer);
            }
    std::vector<Tensor<1, 3>> u;
    std::vector<Tensor<2, 3>> gradient;
    field.evaluate_at(locator.locate(ends), u, gradient);
    std::ostringstream csv;
    csv << "layer,x0_mm,z0_mm,x1_mm,z1_mm,ux0_mm,uz0_mm,ux1_mm,uz1_mm\n"
        << std::setprecision(7);
    for (unsigned int s = 0; s < layers.size(); ++s)
      {
        const unsigned int k = 2 * s;
        csv << layers[s] << ',' << ends[k][0] << ',' << ends[k][2] << ','
            << ends[k + 1][0] << ',' << ends[k + 1][2] << ',' << u[k][0] << ','
            << u[k][2] << ',' << u[k + 1][0] << ',' << u[k + 1][2] << '\n';
      }
    output.write_text("section_septa.csv", csv.str());
  }


  void
  write_force_displacement(const std::vector<double>         &forces,
                           const std::vector<double>         &depths,
                           const std::vector<StepStatistics> &statistics,
                           RunOutput                         &output)
  {
    std::ostringstream csv;
    csv << "step,force_N,depth_mm,newton_iterations,linear_iterations,"
           "load_cuts,wall_time_s\n"
        << std::setprecision(10);
    for (unsigned int k = 0; k < forces.size(); ++k)
      csv << k + 1 << ',' << forces[k] << ',' << depths[k] << ','
          << statistics[k].newton_iterations << ','
          << statistics[k].linear_iterations << ',' << statistics[k].cuts << ','
          << statistics[k].wall_time << '\n';
    output.write_text("force_displacement.csv", csv.str());
  }
} // namespace ssc
