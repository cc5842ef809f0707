#include <deal.II/base/geometry_info.h>
#include <deal.II/base/mpi.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>
#include <sstream>

#include <ssc/materials/material.h>
#include <ssc/mesh/background_mesh.h>
#include <ssc/output/volume_output.h>
#include <ssc/scenes/closure.h>

namespace ssc
{
  namespace
  {
    /// A face of the cut's wall in the skin: its side of the long axis
    /// (+-1), its extent along it, its area and its four vertices
    /// (reference position, dofs of the three components).
    struct WallFace
    {
      int                     side  = 0;
      double                  lower = 0, upper = 0;
      double                  area = 0;
      std::array<Point<3>, 4> X;
      std::array<std::array<types::global_dof_index, 3>, 4> dofs;
    };


    /// The skin's (layer 0) faces on the cut of the locally owned cells,
    /// gathered from every rank.
    std::vector<WallFace>
    skin_wall_faces(const DisplacementField &field, const Incision &incision)
    {
      const unsigned int along                   = incision.direction,
                         across                  = incision.normal_direction();
      constexpr unsigned int                size = 4 + 4 * 6;
      std::vector<std::array<double, size>> local;
      for (const auto &cell : field.dof_handler().active_cell_iterators())
        if (cell->is_locally_owned() && cell->material_id() == 0 &&
            cell->at_boundary())
          for (const unsigned int f : cell->face_indices())
            if (cell->face(f)->at_boundary() &&
                cell->face(f)->boundary_id() == BoundaryId::cut)
              {
                const auto               face = cell->face(f);
                std::array<double, size> entry;
                entry[0] = face->center()[across] > 0 ? 1. : -1.;
                entry[1] = std::numeric_limits<double>::max();
                entry[2] = -std::numeric_limits<double>::max();
                entry[3] = face->measure();
                for (unsigned int k = 0; k < 4; ++k)
                  {
                    const unsigned int v =
                      GeometryInfo<3>::face_to_cell_vertices(f, k);
                    const Point<3> X = cell->vertex(v);
                    entry[1]         = std::min(entry[1], X[along]);
                    entry[2]         = std::max(entry[2], X[along]);
                    const auto dofs  = field.vertex_dofs(cell, v);
                    for (unsigned int d = 0; d < 3; ++d)
                      {
                        entry[4 + 6 * k + d]     = X[d];
                        entry[4 + 6 * k + 3 + d] = dofs[d];
                      }
                  }
                local.push_back(entry);
              }
      std::vector<WallFace> faces;
      for (const auto &rank :
           Utilities::MPI::all_gather(field.dof_handler().get_communicator(),
                                      local))
        for (const auto &e : rank)
          {
            WallFace face;
            face.side  = static_cast<int>(e[0]);
            face.lower = e[1];
            face.upper = e[2];
            face.area  = e[3];
            for (unsigned int k = 0; k < 4; ++k)
              for (unsigned int d = 0; d < 3; ++d)
                {
                  face.X[k][d] = e[4 + 6 * k + d];
                  face.dofs[k][d] =
                    static_cast<types::global_dof_index>(e[4 + 6 * k + 3 + d]);
                }
            faces.push_back(face);
          }
      return faces;
    }


    /// The bite of side @p side at @p station, @p width long: each wall
    /// face's area share inside the band |along - station| <= width / 2,
    /// lumped onto its vertices, normalised to sum 1.
    std::vector<SutureAnchor>
    bite(const std::vector<WallFace> &faces,
         const int                    side,
         const double                 station,
         const double                 width)
    {
      std::map<types::global_dof_index, SutureAnchor> anchors;
      double                                          total = 0;
      for (const WallFace &face : faces)
        {
          if (face.side != side || face.upper <= face.lower)
            continue;
          const double overlap = std::min(face.upper, station + width / 2) -
                                 std::max(face.lower, station - width / 2);
          if (overlap <= 0)
            continue;
          const double share =
            face.area * overlap / (face.upper - face.lower) / 4;
          for (unsigned int k = 0; k < 4; ++k)
            {
              SutureAnchor &anchor = anchors[face.dofs[k][0]];
              anchor.X             = face.X[k];
              anchor.dofs          = face.dofs[k];
              anchor.weight += share;
            }
          total += 4 * share;
        }
      std::vector<SutureAnchor> result;
      for (auto &[dof, anchor] : anchors)
        {
          anchor.weight /= total;
          result.push_back(anchor);
        }
      return result;
    }
  } // namespace


  std::vector<Suture>
  find_sutures(const DisplacementField &field,
               const Incision          &incision,
               const double             spacing,
               const double             bite_width)
  {
    AssertThrow(incision.shape == Incision::Shape::ellipse && spacing > 0 &&
                  bite_width > 0 && bite_width <= spacing,
                ExcMessage("Sutures close an elliptic excision, at a "
                           "positive spacing, with bites no longer than it."));
    const std::vector<WallFace> faces = skin_wall_faces(field, incision);
    const double                half  = incision.length / 2;
    const int                   n =
      static_cast<int>(std::floor((half - bite_width / 2) / spacing + 1e-9));
    std::ostringstream message;
    message << "Incision/Closure: sutures " << spacing << " mm apart with "
            << bite_width << " mm bites on an ellipse " << incision.length
            << " mm long: ";
    AssertThrow(n >= 0 && bite_width / 2 < half,
                ExcMessage(message.str() + "no bite fits on the wound."));
    std::vector<Suture> sutures;
    for (int i = -n; i <= n; ++i)
      {
        Suture suture;
        suture.station = i * spacing;
        suture.a       = bite(faces, 1, suture.station, bite_width);
        suture.b       = bite(faces, -1, suture.station, bite_width);
        AssertThrow(!suture.a.empty() && !suture.b.empty(),
                    ExcMessage(message.str() + "the suture at " +
                               std::to_string(suture.station) +
                               " mm grips no face of the wound's wall in "
                               "the skin."));
        sutures.push_back(suture);
      }
    return sutures;
  }


  double
  ClosureState::mean_force_N() const
  {
    return suture_forces_N.empty() ? 0. :
                                     std::accumulate(suture_forces_N.begin(),
                                                     suture_forces_N.end(),
                                                     0.) /
                                       suture_forces_N.size();
  }


  double
  ClosureState::max_force_N() const
  {
    return suture_forces_N.empty() ?
             0. :
             *std::max_element(suture_forces_N.begin(), suture_forces_N.end());
  }


  nlohmann::ordered_json
  ClosureState::to_json() const
  {
    return {{"n_sutures", suture_forces_N.size()},
            {"suture_stations_mm", stations_mm},
            {"force_per_suture_N", mean_force_N()},
            {"max_suture_force_N", max_force_N()},
            {"suture_forces_N", suture_forces_N},
            {"max_skin_stress_kPa", max_skin_stress_kPa},
            {"max_skin_stress_at_mm", max_stress_at_mm},
            {"dog_ear_height_mm", dog_ear_height_mm},
            {"dog_ear_at_mm", dog_ear_at_mm},
            {"residual_gap_mm", residual_gap_mm}};
  }


  namespace
  {
    /// The largest of @p value over the ranks, with the position @p at of
    /// the rank that has it.
    std::pair<double, std::array<double, 2>>
    max_with_position(const double                 value,
                      const std::array<double, 2> &at,
                      const MPI_Comm               communicator)
    {
      std::pair<double, std::array<double, 2>> best = {value, at};
      for (const auto &[v, p] :
           Utilities::MPI::all_gather(communicator, std::make_pair(value, at)))
        if (v > best.first)
          best = {v, p};
      return best;
    }
  } // namespace


  ClosureState
  measure_closure(const ElasticSystem                 &system,
                  const SutureTies                    &sutures,
                  const TrilinosWrappers::MPI::Vector &before,
                  const double                         fraction)
  {
    const DisplacementField             &field    = system.field();
    const TrilinosWrappers::MPI::Vector &solution = field.solution();
    const MPI_Comm communicator = field.dof_handler().get_communicator();
    ClosureState   state;
    state.fraction = fraction;
    for (const Tensor<1, 3> &force : sutures.forces(solution))
      state.suture_forces_N.push_back(force.norm());
    for (const Suture &suture : sutures.sutures())
      state.stations_mm.push_back(suture.station);
    state.residual_gap_mm = sutures.residual_gap(solution);

    // the skin's stress and the surface's rise, on the locally owned cells
    const std::vector<SymmetricTensor<2, 3>> stresses = cell_cauchy_stresses(
      field, system.materials(), system.growth(), system.history());
    double                stress = 0, rise = 0;
    std::array<double, 2> stress_at = {{0, 0}}, rise_at = {{0, 0}};
    for (const auto &cell : field.dof_handler().active_cell_iterators())
      if (cell->is_locally_owned() && cell->material_id() == 0)
        {
          const double equivalent =
            von_mises(stresses[cell->active_cell_index()]);
          if (equivalent > stress)
            {
              stress    = equivalent;
              stress_at = {{cell->center()[0], cell->center()[1]}};
            }
          for (const unsigned int v : cell->vertex_indices())
            if (std::abs(cell->vertex(v)[2]) < 1e-12)
              {
                const types::global_dof_index dof =
                  field.vertex_dofs(cell, v)[2];
                const double dz = solution[dof] - before[dof];
                if (dz > rise)
                  {
                    rise    = dz;
                    rise_at = {{cell->vertex(v)[0], cell->vertex(v)[1]}};
                  }
              }
        }
    const auto max_stress = max_with_position(stress, stress_at, communicator);
    const auto max_rise   = max_with_position(rise, rise_at, communicator);
    state.max_skin_stress_kPa = 1e3 * max_stress.first; // MPa -> kPa
    state.max_stress_at_mm    = max_stress.second;
    state.dog_ear_height_mm   = max_rise.first;
    state.dog_ear_at_mm       = max_rise.second;
    return state;
  }
} // namespace ssc
