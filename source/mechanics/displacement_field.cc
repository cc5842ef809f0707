#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>

#include <deal.II/dofs/dof_tools.h>

#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>

#include <deal.II/grid/grid_tools.h>

#include <deal.II/numerics/vector_tools.h>

#include <array>
#include <cmath>
#include <iomanip>
#include <map>
#include <set>
#include <sstream>

#include <ssc/mechanics/displacement_field.h>

namespace ssc
{
  DisplacementField::DisplacementField(
    const parallel::distributed::Triangulation<3> &tria,
    const unsigned int                             degree,
    const unsigned int                             mapping_degree)
    : tria(tria)
    , mpi_communicator(tria.get_communicator())
    , finite_element(FE_Q<3>(degree), 3)
    , cell_mapping(mapping_degree)
    , dofs(tria)
  {}


  void
  DisplacementField::distribute_dofs()
  {
    dofs.distribute_dofs(finite_element);
    owned_dofs = dofs.locally_owned_dofs();
    DoFTools::extract_locally_relevant_dofs(dofs, mesh_relevant);
    ghosted_solution.reinit(owned_dofs, mesh_relevant, mpi_communicator);
  }


  void
  DisplacementField::set_relevant_dofs(const IndexSet &relevant)
  {
    const TrilinosWrappers::MPI::Vector owned = owned_solution();
    ghosted_solution.reinit(owned_dofs, relevant, mpi_communicator);
    ghosted_solution = owned;
  }


  std::array<types::global_dof_index, 3>
  DisplacementField::vertex_dofs(
    const DoFHandler<3>::active_cell_iterator &cell,
    const unsigned int                         v) const
  {
    std::array<types::global_dof_index, 3> result;
    const unsigned int n = finite_element.n_dofs_per_vertex();
    for (unsigned int i = 0; i < n; ++i)
      result[finite_element.system_to_component_index(v * n + i).first] =
        cell->vertex_dof_index(v, i);
    return result;
  }


  TrilinosWrappers::MPI::Vector
  DisplacementField::owned_solution() const
  {
    TrilinosWrappers::MPI::Vector owned(owned_dofs, mpi_communicator);
    owned = ghosted_solution;
    return owned;
  }


  void
  DisplacementField::set_solution(const TrilinosWrappers::MPI::Vector &owned)
  {
    ghosted_solution = owned;
  }


  void
  DisplacementField::evaluate_at(const std::vector<PointLocation> &locations,
                                 std::vector<Tensor<1, 3>> &displacements,
                                 std::vector<Tensor<2, 3>> &gradients) const
  {
    displacements.assign(locations.size(), Tensor<1, 3>());
    gradients.assign(locations.size(), Tensor<2, 3>());
    // group the points by cell: one FEValues per cell
    std::map<unsigned int, std::vector<unsigned int>> by_cell;
    for (unsigned int k = 0; k < locations.size(); ++k)
      if (locations[k].cell.state() == IteratorState::valid)
        by_cell[locations[k].cell->active_cell_index()].push_back(k);
    const FEValuesExtractors::Vector displacement(0);
    for (const auto &[index, points] : by_cell)
      {
        std::vector<Point<3>> units;
        for (const unsigned int k : points)
          units.push_back(locations[k].unit_point);
        FEValues<3> fe_values(cell_mapping,
                              finite_element,
                              Quadrature<3>(units),
                              update_values | update_gradients);
        const typename DoFHandler<3>::active_cell_iterator cell(
          &dofs.get_triangulation(),
          locations[points[0]].cell->level(),
          locations[points[0]].cell->index(),
          &dofs);
        fe_values.reinit(cell);
        std::vector<Tensor<1, 3>> u(units.size());
        std::vector<Tensor<2, 3>> grad(units.size());
        fe_values[displacement].get_function_values(ghosted_solution, u);
        fe_values[displacement].get_function_gradients(ghosted_solution, grad);
        for (unsigned int q = 0; q < points.size(); ++q)
          {
            displacements[points[q]] = u[q];
            gradients[points[q]]     = grad[q];
          }
      }
    // each point is owned by exactly one rank: the sum gathers them all
    std::vector<double> values(12 * locations.size());
    for (unsigned int k = 0; k < locations.size(); ++k)
      for (unsigned int d = 0; d < 12; ++d)
        values[12 * k + d] =
          d < 3 ? displacements[k][d] : gradients[k][(d - 3) / 3][(d - 3) % 3];
    Utilities::MPI::sum(values, mpi_communicator, values);
    for (unsigned int k = 0; k < locations.size(); ++k)
      for (unsigned int d = 0; d < 12; ++d)
        (d < 3 ? displacements[k][d] : gradients[k][(d - 3) / 3][(d - 3) % 3]) =
          values[12 * k + d];
  }


  Tensor<1, 3>
  DisplacementField::point_value(const Point<3> &p) const
  {
    Tensor<1, 3> value;
    double       found = 0;
    try
      {
        const auto cell_and_point =
          GridTools::find_active_cell_around_point(cell_mapping, dofs, p);
        if (cell_and_point.first->is_locally_owned())
          {
            const Quadrature<3> q(
              GeometryInfo<3>::project_to_unit_cell(cell_and_point.second));
            FEValues<3> fe_values(cell_mapping,
                                  finite_element,
                                  q,
                                  update_values);
            fe_values.reinit(cell_and_point.first);
            std::vector<Vector<double>> values(1, Vector<double>(3));
            fe_values.get_function_values(ghosted_solution, values);
            for (unsigned int d = 0; d < 3; ++d)
              value[d] = values[0][d];
            found = 1;
          }
      }
    catch (...)
      {
        // not on this rank
      }
    found = Utilities::MPI::sum(found, mpi_communicator);
    AssertThrow(found > 0,
                ExcMessage("Point outside the mesh in point_value()."));
    value = Utilities::MPI::sum(value, mpi_communicator);
    return value / found;
  }


  std::pair<double, double>
  DisplacementField::errors(const Function<3> &exact_solution) const
  {
    const QGauss<3> quadrature(finite_element.degree + 2);
    Vector<float>   cell_errors(dofs.get_triangulation().n_active_cells());
    const auto      global_error = [&](const VectorTools::NormType norm) {
      VectorTools::integrate_difference(cell_mapping,
                                        dofs,
                                        ghosted_solution,
                                        exact_solution,
                                        cell_errors,
                                        quadrature,
                                        norm);
      return VectorTools::compute_global_error(dofs.get_triangulation(),
                                               cell_errors,
                                               norm);
    };
    return {global_error(VectorTools::L2_norm),
            global_error(VectorTools::H1_seminorm)};
  }


  std::string
  DisplacementField::describe(const TrilinosWrappers::MPI::Vector &du) const
  {
    std::map<types::global_dof_index, Point<3>> support_points;
    DoFTools::map_dofs_to_support_points(cell_mapping, dofs, support_points);
    // over the nodes, w = |du|^2 at the node: sums of w, w r, w r^2, w z,
    // w z^2 and of the squares of the radial, hoop and vertical components
    std::vector<double> sums(8, 0.);
    // the largest nodal |du| and where it is
    std::vector<double>                  largest(4, 0.);
    std::vector<types::global_dof_index> cell_dofs(
      finite_element.n_dofs_per_cell());
    std::set<types::global_dof_index> visited;
    const unsigned int                n_nodes =
      finite_element.base_element(0).n_dofs_per_cell();
    for (const auto &cell : dofs.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          cell->get_dof_indices(cell_dofs);
          for (unsigned int k = 0; k < n_nodes; ++k)
            {
              std::array<types::global_dof_index, 3> dofs;
              for (unsigned int c = 0; c < 3; ++c)
                dofs[c] =
                  cell_dofs[finite_element.component_to_system_index(c, k)];
              if (!owned_dofs.is_element(dofs[0]) ||
                  !visited.insert(dofs[0]).second)
                continue;
              const Tensor<1, 3> d({du[dofs[0]], du[dofs[1]], du[dofs[2]]});
              const double       w = d.norm_square();
              if (w == 0.)
                continue;
              const Point<3> &x      = support_points.at(dofs[0]);
              const double    r      = std::hypot(x[0], x[1]);
              const double    radial = r > 0 ? (d[0] * x[0] + d[1] * x[1]) / r :
                                               std::hypot(d[0], d[1]);
              const double hoop = r > 0 ? (d[1] * x[0] - d[0] * x[1]) / r : 0.;
              sums[0] += w;
              sums[1] += w * r;
              sums[2] += w * r * r;
              sums[3] += w * x[2];
              sums[4] += w * x[2] * x[2];
              sums[5] += radial * radial;
              sums[6] += hoop * hoop;
              sums[7] += d[2] * d[2];
              if (std::sqrt(w) > largest[0])
                largest = {std::sqrt(w), x[0], x[1], x[2]};
            }
        }
    std::vector<double> total(sums.size());
    Utilities::MPI::sum(sums, mpi_communicator, total);
    for (const auto &l : Utilities::MPI::all_gather(mpi_communicator, largest))
      if (l[0] > largest[0])
        largest = l;
    if (total[0] == 0.)
      return "du = 0";
    const auto spread = [&](const double sum, const double sum_of_squares) {
      const double mean = sum / total[0];
      return std::make_pair(
        mean, std::sqrt(std::max(0., sum_of_squares / total[0] - mean * mean)));
    };
    const auto [r_mean, r_spread] = spread(total[1], total[2]);
    const auto [z_mean, z_spread] = spread(total[3], total[4]);
    std::ostringstream text;
    text << std::setprecision(3) << "|du|^2 centred at r = " << r_mean << " +- "
         << r_spread << " mm, z = " << z_mean << " +- " << z_spread
         << " mm; radial/hoop/vertical shares " << total[5] / total[0] << '/'
         << total[6] / total[0] << '/' << total[7] / total[0] << "; largest "
         << largest[0] << " (" << largest[0] / std::sqrt(total[0])
         << " of |du|) at (" << largest[1] << ", " << largest[2] << ", "
         << largest[3] << ") mm";
    return text.str();
  }
} // namespace ssc
