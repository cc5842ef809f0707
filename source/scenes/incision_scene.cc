#include <deal.II/base/timer.h>

#include <array>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>

#include <ssc/base/surface_expression.h>
#include <ssc/materials/gasser_ogden_holzapfel_material.h>
#include <ssc/output/field_output.h>
#include <ssc/scenes/incision_scene.h>
#include <ssc/scenes/mechanics_model.h>
#include <ssc/scenes/quasi_static_driver.h>
#include <ssc/scenes/scene_run.h>
#include <ssc/scenes/support_conditions.h>

namespace ssc
{
  namespace
  {
    /// The angle (degrees from x) of Langer's lines at the patch centre
    /// where the skin's law has them, NaN otherwise.
    double
    langer_line_angle_at_centre(const Parameters &parameters)
    {
      const Layer &skin  = parameters.layers.layer(0);
      const auto *fibres = dynamic_cast<const GasserOgdenHolzapfelParameters *>(
        &parameters.materials.of(skin.name, skin.material_model));
      if (fibres == nullptr)
        return std::numeric_limits<double>::quiet_NaN();
      return parse_surface_expression(fibres->langer_line_angle,
                                      "Langer line angle")
        ->value(Point<2>());
    }

    /// "along" or "across" Langer's lines at angle @p langer (degrees) for
    /// a cut at @p cut degrees; "" without lines.
    std::string
    relative_to_lines(const double cut, const double langer)
    {
      if (std::isnan(langer))
        return "";
      const double difference = std::abs(std::remainder(cut - langer, 180.));
      AssertThrow(difference < 1e-6 || std::abs(difference - 90.) < 1e-6,
                  ExcMessage("The incision scene cuts along x and y, along "
                             "and across Langer's lines; the skin's Langer "
                             "line angle at the patch centre is " +
                             std::to_string(langer) +
                             " degrees: give 0 or 90 (the direction of the "
                             "lines relative to the cut is what matters)."));
      return difference < 45. ? "along" : "across";
    }


    /**
     * The skin's plane tension far from the cut, N/m, along x and y: its law
     * (at full pre-tension) at F = diag(1, 1, lambda), the sides held and
     * lambda such that its free surface carries no normal stress, the
     * in-plane Cauchy stress times the deformed thickness. The number to
     * compare with in vivo skin tension (Flynn et al. 2011).
     */
    std::array<double, 2>
    far_field_skin_tension(const Material &skin, const double thickness)
    {
      const Point<3> X(0, 0, -thickness / 2);
      const auto     stress = [&](const double lambda) {
        Tensor<2, 3> F = unit_symmetric_tensor<3>();
        F[2][2]        = lambda;
        return skin.cauchy_stress(X, F);
      };
      double low = 0.2, high = 5.;
      AssertThrow(stress(low)[2][2] < 0 && stress(high)[2][2] > 0,
                  ExcMessage("The skin's free-surface thickness under its "
                             "pre-tension is not between 0.2 and 5 times the "
                             "imaged one."));
      for (unsigned int k = 0; k < 100 && high - low > 1e-12; ++k)
        {
          const double mid                     = (low + high) / 2;
          (stress(mid)[2][2] < 0 ? low : high) = mid;
        }
      const double                lambda = (low + high) / 2;
      const SymmetricTensor<2, 3> sigma  = stress(lambda);
      // N/mm -> N/m
      return {{1e3 * sigma[0][0] * thickness * lambda,
               1e3 * sigma[1][1] * thickness * lambda}};
    }
  } // namespace


  std::vector<WoundShape>
  IncisionScene::run()
  {
    SceneRun            scene(parameters, mpi_communicator, "incision");
    const double        langer = langer_line_angle_at_centre(parameters);
    const unsigned int  steps  = parameters.incision.load_steps;
    std::vector<double> fractions;
    for (unsigned int step = 1; step <= steps; ++step)
      fractions.push_back(double(step) / steps);

    std::array<double, 2>    tension = {{0, 0}};
    std::vector<WoundShape>  wounds;
    std::ostringstream       table, lips;
    nlohmann::ordered_json   cuts, solver;
    types::global_dof_index  dofs  = 0;
    types::global_cell_index cells = 0;
    table << "cut,step,prestretch_fraction,gap_mm,area_mm2,length_mm,"
             "aspect_ratio,orientation_deg\n";
    const bool disc = parameters.incision.shape == Incision::Shape::disc;
    for (unsigned int direction = 0; direction < (disc ? 1u : 2u); ++direction)
      {
        const Incision incision =
          parameters.incision.incision(parameters.layers, direction);
        const std::string name = disc ? "disc" : direction == 0 ? "x" : "y";
        const std::string where =
          disc ? "" : relative_to_lines(90. * direction, langer);
        if (disc)
          scene.pcout() << "Excision of a disc (" << incision.length
                        << " mm across";
        else
          scene.pcout() << "Incision along " << name << " (" << incision.length
                        << " mm";
        scene.pcout() << " through " << incision.n_cut_layers << " layer(s)"
                      << (where.empty() ? "" : ", " + where + " Langer's lines")
                      << ")" << std::endl;
        MechanicsModel model(parameters, scene, incision);
        ElasticSystem &system = model.system();
        {
          TimerOutput::Scope t(scene.timer(), "setup");
          system.setup(support_conditions(parameters.elasticity.sides));
        }
        QuasiStaticDriver driver(system,
                                 parameters.newton,
                                 scene.pcout(),
                                 !parameters.run.test_mode);
        WoundShape        wound;
        driver.run(
          fractions,
          [&system](const double f) { system.set_prestretch_fraction(f); },
          1. / parameters.newton.initial_steps,
          LoadDependence::tangent,
          [&](const unsigned int k) {
            TimerOutput::Scope t(scene.timer(), "output");
            wound = measure_wound(system.field(), incision);
            scene.pcout() << "  pre-tension " << std::setprecision(4)
                          << 100 * fractions[k] << " %: gap " << wound.gap_mm
                          << " mm, area " << wound.area_mm2 << " mm^2, length "
                          << wound.length_mm << " mm";
            if (disc)
              scene.pcout() << ", area change " << wound.area_change_pct
                            << " %, aspect ratio " << wound.aspect_ratio;
            scene.pcout() << std::endl;
            table << name << ',' << k + 1 << ',' << fractions[k] << ','
                  << wound.gap_mm << ',' << wound.area_mm2 << ','
                  << wound.length_mm << ',' << wound.aspect_ratio << ','
                  << wound.orientation_deg << '\n';
          });
        if (parameters.run.write_fields)
          {
            TimerOutput::Scope t(scene.timer(), "output");
            FieldOutput(system, model.coupling(), Kinematics::finite_strain)
              .write(scene.output(), direction + 1, direction);
          }
        std::istringstream rows(wound.lips_csv());
        std::string        row;
        std::getline(rows, row);
        if (direction == 0)
          lips << "cut," << row << '\n';
        while (std::getline(rows, row))
          lips << name << ',' << row << '\n';

        nlohmann::ordered_json entry      = wound.to_json();
        entry["relative_to_langer_lines"] = where.empty() ?
                                              nlohmann::ordered_json() :
                                              nlohmann::ordered_json(where);
        const std::string key = disc ? "excision" : "cut_along_" + name;
        cuts[key]             = entry;
        solver[key]           = driver.summary();
        tension =
          far_field_skin_tension(system.materials()[0],
                                 parameters.layers.layer(0).thickness(0, 0));
        dofs  = system.field().dof_handler().n_dofs();
        cells = model.mesh().triangulation().n_global_active_cells();
        wounds.push_back(wound);
      }

    nlohmann::ordered_json summary = scene.summary(dofs, cells);
    // the interface's totals over both cuts, and each cut's own record
    nlohmann::ordered_json totals = {{"linear_iterations", 0},
                                     {"newton_iterations", 0}};
    for (const auto &record : solver)
      for (const char *key : {"linear_iterations", "newton_iterations"})
        totals[key] =
          totals[key].get<unsigned int>() + record[key].get<unsigned int>();
    totals["preconditioner"] = solver.begin().value()["preconditioner"];
    totals["per_cut"]        = solver;
    summary["solver"]        = totals;
    nlohmann::ordered_json wound_summary;
    wound_summary["langer_line_angle_deg"] = std::isnan(langer) ?
                                               nlohmann::ordered_json() :
                                               nlohmann::ordered_json(langer);
    wound_summary["skin_tension_N_per_m"]  = {{"x", tension[0]},
                                              {"y", tension[1]}};
    if (disc)
      {
        wound_summary.update(cuts["excision"]);
        // the freed disc relaxes to the skin's stress-free state, whatever
        // its law: its area changes by 1 / s^2 (of the skin alone; a disc
        // with fat attached would shrink less)
        const double s  = parameters.layers.layer(0).prestretch;
        summary["disc"] = {{"area_change_pct", 100. * (1. / (s * s) - 1.)}};
      }
    else
      wound_summary.update(cuts);
    if (!disc && !std::isnan(langer))
      {
        const unsigned int across =
          relative_to_lines(0., langer) == "across" ? 0 : 1;
        wound_summary["gap_ratio_across_to_along"] =
          wounds[across].gap_mm / wounds[1 - across].gap_mm;
      }
    else if (!disc)
      wound_summary["gap_ratio_x_to_y"] = wounds[0].gap_mm / wounds[1].gap_mm;
    summary["wound"] = wound_summary;
    {
      TimerOutput::Scope t(scene.timer(), "output");
      scene.output().write_text("wound.csv", table.str());
      scene.output().write_text("wound_lips.csv", lips.str());
      scene.output().write_summary(summary);
    }
    scene.pcout() << "Skin tension far from the cut: " << tension[0]
                  << " N/m along x, " << tension[1] << " N/m along y"
                  << std::endl;
    scene.print_wall_times();
    return wounds;
  }
} // namespace ssc
