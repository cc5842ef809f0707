#include <deal.II/base/mpi.h>

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
    return {{"planned_length_mm", planned_length},
            {"cut_direction_deg", direction == 0 ? 0. : 90.},
            {"gap_mm", gap_mm},
            {"area_mm2", area_mm2},
            // an incision plans no area: its change has no reference
            {"area_change_pct", nullptr},
            {"length_mm", length_mm},
            {"aspect_ratio", aspect_ratio},
            {"orientation_deg", orientation_deg}};
  }


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
    const unsigned int along                      = incision.direction,
                       across                     = incision.normal_direction();
    const FESystem<3>                   &fe       = field.fe();
    const TrilinosWrappers::MPI::Vector &solution = field.solution();
    const double tolerance = 1e-9 * (1. + incision.length);

    // (side, t) -> deformed position, of the locally owned cells
    std::vector<std::array<double, 5>> local;
    for (const auto &cell : field.dof_handler().active_cell_iterators())
      if (cell->is_locally_owned() && cell->at_boundary())
        {
          bool on_cut = false;
          for (const auto &face : cell->face_iterators())
            on_cut |=
              face->at_boundary() && face->boundary_id() == BoundaryId::cut;
          if (!on_cut)
            continue;
          const int side = cell->center()[across] > 0 ? 1 : -1;
          for (const unsigned int v : cell->vertex_indices())
            {
              const Point<3> X = cell->vertex(v);
              if (std::abs(X[across]) > tolerance || std::abs(X[2]) > tolerance)
                continue;
              Point<3> x = X;
              for (unsigned int i = 0; i < fe.n_dofs_per_vertex(); ++i)
                x[fe.system_to_component_index(v * fe.n_dofs_per_vertex() + i)
                    .first] += solution(cell->vertex_dof_index(v, i));
              local.push_back({double(side), X[along], x[0], x[1], x[2]});
            }
        }

    std::map<std::pair<int, double>, Point<3>> lips;
    for (const auto &rank :
         Utilities::MPI::all_gather(field.dof_handler().get_communicator(),
                                    local))
      for (const auto &p : rank)
        lips[{static_cast<int>(p[0]), p[1]}] = Point<3>(p[2], p[3], p[4]);

    WoundShape wound;
    wound.planned_length = incision.length;
    wound.direction      = incision.direction;
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
    // shoelace over the outline: one lip forwards, the other back
    std::vector<Point<3>> outline;
    for (const auto &p : upper)
      outline.push_back(p.second);
    for (auto p = lower.rbegin(); p != lower.rend(); ++p)
      outline.push_back(p->second);
    double twice_area = 0;
    for (unsigned int k = 0; k < outline.size(); ++k)
      {
        const Point<3> &a = outline[k], &b = outline[(k + 1) % outline.size()];
        twice_area += a[0] * b[1] - b[0] * a[1];
      }
    wound.area_mm2          = std::abs(twice_area) / 2;
    const Tensor<1, 3> axis = lower.back().second - lower.front().second;
    wound.length_mm         = std::hypot(axis[0], axis[1]);
    wound.aspect_ratio = wound.gap_mm > 0 ? wound.length_mm / wound.gap_mm : 0.;
    wound.orientation_deg = std::atan2(axis[1], axis[0]) * 180. / M_PI;
    if (wound.orientation_deg < 0)
      wound.orientation_deg += 180;
    if (wound.orientation_deg >= 180)
      wound.orientation_deg -= 180;
    return wound;
  }
} // namespace ssc
