#include <deal.II/base/mpi.h>
#include <deal.II/base/symmetric_tensor.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>
#include <utility>

#include <ssc/mesh/background_mesh.h>
#include <ssc/scenes/wound.h>

namespace ssc
{
  nlohmann::ordered_json
  WoundShape::to_json() const
  {
    const bool             disc = shape != Incision::Shape::line;
    nlohmann::ordered_json json;
    if (shape == Incision::Shape::disc)
      {
        json["planned_diameter_mm"] = planned_length;
        json["planned_area_mm2"]    = planned_area_mm2;
      }
    else if (shape == Incision::Shape::ellipse)
      {
        json["planned_length_mm"]       = planned_length;
        json["planned_width_mm"]        = planned_width;
        json["planned_area_mm2"]        = planned_area_mm2;
        json["long_axis_direction_deg"] = direction == 0 ? 0. : 90.;
      }
    else
      {
        json["planned_length_mm"] = planned_length;
        json["cut_direction_deg"] = direction == 0 ? 0. : 90.;
      }
    json["gap_mm"]   = gap_mm;
    json["area_mm2"] = area_mm2;
    // an incision plans no area: its change has no reference
    json["area_change_pct"] =
      disc ? nlohmann::ordered_json(area_change_pct) : nlohmann::ordered_json();
    json["length_mm"]       = length_mm;
    json["aspect_ratio"]    = aspect_ratio;
    json["orientation_deg"] = orientation_deg;
    return json;
  }


  namespace
  {
    /// Angle of @p axis from x, degrees in [0, 180).
    double
    axis_angle(const double x, const double y)
    {
      double angle = std::atan2(y, x) * 180. / M_PI;
      if (angle < 0)
        angle += 180;
      if (angle >= 180)
        angle -= 180;
      return angle;
    }


    /// Area of the closed polygon @p outline projected on the plane z = 0
    /// (positive), and its centroidal second moments of area divided by the
    /// area, C = int (x - c)(x - c)^T dA / A (2 x 2).
    double
    polygon_moments(const std::vector<Point<3>> &outline,
                    SymmetricTensor<2, 2>       &C)
    {
      double area = 0, cx = 0, cy = 0, xx = 0, yy = 0, xy = 0;
      for (unsigned int k = 0; k < outline.size(); ++k)
        {
          const Point<3> &a = outline[k],
                         &b = outline[(k + 1) % outline.size()];
          const double c    = a[0] * b[1] - b[0] * a[1];
          area += c / 2;
          cx += (a[0] + b[0]) * c / 6;
          cy += (a[1] + b[1]) * c / 6;
          xx += (a[0] * a[0] + a[0] * b[0] + b[0] * b[0]) * c / 12;
          yy += (a[1] * a[1] + a[1] * b[1] + b[1] * b[1]) * c / 12;
          xy +=
            (a[0] * b[1] + 2 * a[0] * a[1] + 2 * b[0] * b[1] + b[0] * a[1]) *
            c / 24;
        }
      if (area == 0) // a closed wound: no moments
        return 0;
      // the orientation's sign cancels in every ratio to the area
      cx /= area;
      cy /= area;
      C[0][0] = xx / area - cx * cx;
      C[1][1] = yy / area - cy * cy;
      C[0][1] = xy / area - cx * cy;
      return std::abs(area);
    }


    /// The rim of an excision: the deformed positions of the skin-surface
    /// vertices on its edge by their angle, and the planned rim, the same
    /// vertices on the disc or ellipse before loading (@p planned_rim).
    void
    measure_excision(
      const std::map<std::pair<int, double>, Point<3>> &rim,
      const std::map<std::pair<int, double>, Point<3>> &planned_rim,
      WoundShape                                       &wound)
    {
      std::vector<Point<3>> outline, planned;
      for (const auto &[key, x] : rim)
        {
          wound.lips.push_back({0, key.second, x});
          outline.push_back(x);
          planned.push_back(planned_rim.at(key));
        }
      AssertThrow(outline.size() >= 8,
                  ExcMessage("The excision's rim was not found on the mesh (" +
                             std::to_string(outline.size()) + " points)."));
      SymmetricTensor<2, 2> C, C_planned;
      wound.area_mm2         = polygon_moments(outline, C);
      wound.planned_area_mm2 = polygon_moments(planned, C_planned);
      wound.area_change_pct =
        100. * (wound.area_mm2 / wound.planned_area_mm2 - 1.);
      // the ellipse of the same area and moments: C = diag(a^2, b^2) / 4
      const auto eigen = eigenvectors(C);
      wound.length_mm  = 4. * std::sqrt(std::max(eigen[0].first, 0.));
      wound.gap_mm     = 4. * std::sqrt(std::max(eigen[1].first, 0.));
      wound.aspect_ratio =
        wound.gap_mm > 0 ? wound.length_mm / wound.gap_mm : 0.;
      wound.orientation_deg =
        axis_angle(eigen[0].second[0], eigen[0].second[1]);
    }
  } // namespace


  std::string
  WoundShape::lips_csv() const
  {
    std::ostringstream csv;
    csv.precision(10);
    csv << "side,t,x,y,z\n";
    for (const WoundLipPoint &p : lips)
      csv << p.side << ',' << p.t << ',' << p.position[0] << ','
          << p.position[1] << ',' << p.position[2] << '\n';
    return csv.str();
  }


  WoundShape
  measure_wound(const DisplacementField &field, const Incision &incision)
  {
    const bool         disc                       = incision.excision();
    const auto         semi                       = incision.semi_axes();
    const unsigned int along                      = incision.direction,
                       across                     = incision.normal_direction();
    const TrilinosWrappers::MPI::Vector &solution = field.solution();
    const double tolerance = 1e-9 * (1. + incision.length);

    // (side, t) -> deformed and reference position, of the locally owned
    // cells
    std::vector<std::array<double, 7>> local;
    for (const auto &cell : field.dof_handler().active_cell_iterators())
      if (cell->is_locally_owned() && cell->at_boundary())
        {
          bool on_cut = false;
          for (const auto &face : cell->face_iterators())
            on_cut |=
              face->at_boundary() && face->boundary_id() == BoundaryId::cut;
          if (!on_cut)
            continue;
          const int side = disc ? 0 : cell->center()[across] > 0 ? 1 : -1;
          for (const unsigned int v : cell->vertex_indices())
            {
              const Point<3> X = cell->vertex(v);
              const double   r = std::hypot(X[0] / semi[0], X[1] / semi[1]);
              if (std::abs(X[2]) > tolerance ||
                  (disc ? std::abs(r - 1.) > tolerance / incision.length :
                          std::abs(X[across]) > tolerance))
                continue;
              const auto dofs = field.vertex_dofs(cell, v);
              Point<3>   x    = X;
              for (unsigned int d = 0; d < 3; ++d)
                x[d] += solution(dofs[d]);
              local.push_back({{double(side),
                                disc ? std::atan2(X[1], X[0]) : X[along],
                                x[0],
                                x[1],
                                x[2],
                                X[0],
                                X[1]}});
            }
        }

    std::map<std::pair<int, double>, Point<3>> lips, planned;
    for (const auto &rank :
         Utilities::MPI::all_gather(field.dof_handler().get_communicator(),
                                    local))
      for (const auto &p : rank)
        {
          lips[{static_cast<int>(p[0]), p[1]}]    = Point<3>(p[2], p[3], p[4]);
          planned[{static_cast<int>(p[0]), p[1]}] = Point<3>(p[5], p[6], 0.);
        }

    WoundShape wound;
    wound.shape          = incision.shape;
    wound.planned_length = incision.length;
    wound.planned_width  = incision.width;
    wound.direction      = incision.direction;
    if (disc)
      {
        measure_excision(lips, planned, wound);
        return wound;
      }
    std::vector<std::pair<double, Point<3>>> lower, upper;
    for (const auto &[key, x] : lips)
      {
        wound.lips.push_back({key.first, key.second, x});
        (key.first < 0 ? lower : upper).emplace_back(key.second, x);
      }
    AssertThrow(!lower.empty() && lower.size() == upper.size(),
                ExcMessage("The incision's lips were not found on the mesh "
                           "(" +
                           std::to_string(lower.size()) + " and " +
                           std::to_string(upper.size()) + " points)."));
    // the same reference points on both lips (sorted by t), the ends shared
    for (unsigned int k = 0; k < lower.size(); ++k)
      wound.gap_mm =
        std::max(wound.gap_mm, lower[k].second.distance(upper[k].second));
    // the outline: one lip forwards, the other back
    std::vector<Point<3>> outline;
    for (const auto &p : upper)
      outline.push_back(p.second);
    for (auto p = lower.rbegin(); p != lower.rend(); ++p)
      outline.push_back(p->second);
    SymmetricTensor<2, 2> moments;
    wound.area_mm2          = polygon_moments(outline, moments);
    const Tensor<1, 3> axis = lower.back().second - lower.front().second;
    wound.length_mm         = std::hypot(axis[0], axis[1]);
    wound.aspect_ratio = wound.gap_mm > 0 ? wound.length_mm / wound.gap_mm : 0.;
    wound.orientation_deg = axis_angle(axis[0], axis[1]);
    return wound;
  }
} // namespace ssc
