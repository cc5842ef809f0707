#include <deal.II/base/mpi.templates.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/utilities.h>

#include <deal.II/dofs/dof_tools.h>

#include <deal.II/fe/fe_q.h>

#include <deal.II/grid/grid_tools.h>

#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/trilinos_solver.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>

#include <deal.II/numerics/data_out.h>
#include <deal.II/numerics/vector_tools.h>

#include <Epetra_MultiVector.h>
#include <Teuchos_ParameterList.hpp>
#include <ssc/mechanics/corotational_material.h>
#include <ssc/mechanics/linear_elastic_material.h>
#include <ssc/mechanics/neo_hookean_material.h>
#include <ssc/mechanics/volume_elasticity.h>

#include <array>
#include <iomanip>
#include <limits>
#include <map>
#include <set>
#include <sstream>

namespace ssc
{
  VolumeElasticity::VolumeElasticity(BackgroundMesh             &mesh,
                                     const LayerStack           &layers,
                                     const ElasticityParameters &parameters,
                                     TimerOutput                &timer,
                                     ConditionalOStream         &pcout)
    : mesh(mesh)
    , layers(layers)
    , parameters(parameters)
    , timer(timer)
    , pcout(pcout)
    , mpi_communicator(mesh.triangulation().get_communicator())
    , fe(FE_Q<3>(parameters.degree), 3)
    , mapping(1)
    , dof_handler(mesh.triangulation())
    , cell_quadrature(parameters.degree + 1)
    , assembly_flags(update_values | update_gradients |
                     update_quadrature_points | update_JxW_values)
  {}


  VolumeElasticity::~VolumeElasticity()
  {
    // The preconditioner references the near-null space: release it first.
    preconditioner.clear();
    near_null_space.reset();
  }


  void
  VolumeElasticity::setup_dofs()
  {
    dof_handler.distribute_dofs(fe);
    locally_owned_dofs = dof_handler.locally_owned_dofs();
    DoFTools::extract_locally_relevant_dofs(dof_handler, mesh_relevant_dofs);
    locally_relevant_dofs = mesh_relevant_dofs;
    locally_relevant_solution.reinit(locally_owned_dofs,
                                     locally_relevant_dofs,
                                     mpi_communicator);
  }


  void
  VolumeElasticity::attach(const CellContribution &contribution)
  {
    contributions.push_back(&contribution);
  }


  void
  VolumeElasticity::attach(const DofContribution &contribution)
  {
    dof_contributions.push_back(&contribution);
  }


  void
  VolumeElasticity::evaluate_at(const std::vector<PointLocation> &locations,
                                std::vector<Tensor<1, 3>>        &displacements,
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
        FEValues<3>                                        fe_values(mapping,
                              fe,
                              Quadrature<3>(units),
                              update_values | update_gradients);
        const typename DoFHandler<3>::active_cell_iterator cell(
          &mesh.triangulation(),
          locations[points[0]].cell->level(),
          locations[points[0]].cell->index(),
          &dof_handler);
        fe_values.reinit(cell);
        std::vector<Tensor<1, 3>> u(units.size());
        std::vector<Tensor<2, 3>> grad(units.size());
        fe_values[displacement].get_function_values(locally_relevant_solution,
                                                    u);
        fe_values[displacement].get_function_gradients(
          locally_relevant_solution, grad);
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


  void
  VolumeElasticity::setup_system(
    const std::vector<DirichletCondition> &conditions,
    const std::vector<TiedCondition>      &ties)
  {
    const Quadrature<2> support_points(fe.get_unit_face_support_points());
    FEFaceValues<3>     fe_face_values(mapping,
                                   fe,
                                   support_points,
                                   update_quadrature_points);
    std::vector<types::global_dof_index> face_dofs(fe.n_dofs_per_face());
    // Calls f(dof, support point, component) for every dof on the locally
    // relevant faces of boundary @p id.
    const auto for_boundary_dofs = [&](const types::boundary_id id,
                                       const auto              &f) {
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (!cell->is_artificial())
          for (const unsigned int face : cell->face_indices())
            if (cell->face(face)->at_boundary() &&
                cell->face(face)->boundary_id() == id)
              {
                fe_face_values.reinit(cell, face);
                cell->face(face)->get_dof_indices(face_dofs);
                for (unsigned int i = 0; i < face_dofs.size(); ++i)
                  f(face_dofs[i],
                    fe_face_values.quadrature_point(i),
                    fe.face_system_to_component_index(i).first);
              }
    };

    // The master of each tie: the dof nearest to master_near (smallest index
    // on ties), agreed on by all ranks and made locally relevant everywhere
    // so that every rank can resolve u_i = u_master.
    tie_masters.clear();
    locally_relevant_dofs = mesh_relevant_dofs;
    for (const TiedCondition &tie : ties)
      {
        double                  nearest = std::numeric_limits<double>::max();
        types::global_dof_index master  = numbers::invalid_dof_index;
        for_boundary_dofs(tie.boundary_id,
                          [&](const types::global_dof_index dof,
                              const Point<3>               &p,
                              const unsigned int            component) {
                            if (component != tie.component ||
                                (tie.region && !tie.region(p)))
                              return;
                            const double d = p.distance(tie.master_near);
                            if (d < nearest || (d == nearest && dof < master))
                              {
                                nearest = d;
                                master  = dof;
                              }
                          });
        const double global_nearest =
          Utilities::MPI::min(nearest, mpi_communicator);
        AssertThrow(global_nearest < std::numeric_limits<double>::max(),
                    ExcMessage("A tied boundary condition (rigid punch) "
                               "holds no degree of freedom: is the punch "
                               "smaller than the mesh cells?"));
        if (nearest != global_nearest)
          master = numbers::invalid_dof_index;
        master = Utilities::MPI::min(master, mpi_communicator);
        tie_masters.push_back(master);
        locally_relevant_dofs.add_index(master);
      }
    locally_relevant_dofs.compress();
    if (!ties.empty())
      locally_relevant_solution.reinit(locally_owned_dofs,
                                       locally_relevant_dofs,
                                       mpi_communicator);
    relevant_components.assign(locally_relevant_dofs.n_elements(), 0);
    {
      std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (!cell->is_artificial())
          {
            cell->get_dof_indices(dofs);
            for (unsigned int i = 0; i < dofs.size(); ++i)
              relevant_components[locally_relevant_dofs.index_within_set(
                dofs[i])] = fe.system_to_component_index(i).first;
          }
      // a master may lie on cells this rank does not see
      for (unsigned int t = 0; t < ties.size(); ++t)
        relevant_components[locally_relevant_dofs.index_within_set(
          tie_masters[t])] = ties[t].component;
    }

    hanging_node_constraints.clear();
    hanging_node_constraints.reinit(locally_relevant_dofs);
    DoFTools::make_hanging_node_constraints(dof_handler,
                                            hanging_node_constraints);
    hanging_node_constraints.close();

    constraints.clear();
    constraints.reinit(locally_relevant_dofs);
    constraints.merge(hanging_node_constraints);

    // Dirichlet values at the face support points of every locally relevant
    // boundary face; the first condition that claims a dof wins. The
    // condition's dofs are remembered for its reaction force.
    constrained_dofs_per_condition.assign(conditions.size() + ties.size(),
                                          IndexSet(dof_handler.n_dofs()));
    dirichlet_values.clear();
    for (unsigned int c = 0; c < conditions.size(); ++c)
      {
        const DirichletCondition &condition = conditions[c];
        for_boundary_dofs(condition.boundary_id,
                          [&](const types::global_dof_index dof,
                              const Point<3>               &p,
                              const unsigned int            component) {
                            if (!condition.components[component] ||
                                constraints.is_constrained(dof) ||
                                (condition.region && !condition.region(p)))
                              return;
                            constraints.add_line(dof);
                            const double value =
                              condition.values->value(p, component);
                            constraints.set_inhomogeneity(dof, value);
                            dirichlet_values.emplace_back(dof, value);
                            constrained_dofs_per_condition[c].add_index(dof);
                          });
        constrained_dofs_per_condition[c].compress();
      }
    // A tie's master can be relevant on a rank that sees none of its faces
    // (it was added above), so only the ranks that do see them know a
    // Dirichlet condition on it (displacement control with the edge
    // contact). Every rank must constrain it alike: otherwise the blocks
    // the others add to its row (the contact's punch height) survive as a
    // residual that Newton's method cannot remove.
    for (const types::global_dof_index master : tie_masters)
      {
        unsigned int condition = numbers::invalid_unsigned_int;
        for (unsigned int c = 0; c < conditions.size(); ++c)
          if (condition == numbers::invalid_unsigned_int &&
              constrained_dofs_per_condition[c].is_element(master))
            condition = c;
        double value = condition == numbers::invalid_unsigned_int ?
                         -std::numeric_limits<double>::max() :
                         constraints.get_inhomogeneity(master);
        condition    = Utilities::MPI::min(condition, mpi_communicator);
        value        = Utilities::MPI::max(value, mpi_communicator);
        if (condition == numbers::invalid_unsigned_int ||
            constraints.is_constrained(master))
          continue;
        constraints.add_line(master);
        constraints.set_inhomogeneity(master, value);
        dirichlet_values.emplace_back(master, value);
        constrained_dofs_per_condition[condition].add_index(master);
      }
    // Ties: u_i = u_master; their reaction counts as condition
    // conditions.size() + t (the master included).
    for (unsigned int t = 0; t < ties.size(); ++t)
      {
        const TiedCondition &tie = ties[t];
        IndexSet &tied = constrained_dofs_per_condition[conditions.size() + t];
        tied.add_index(tie_masters[t]);
        for_boundary_dofs(tie.boundary_id,
                          [&](const types::global_dof_index dof,
                              const Point<3>               &p,
                              const unsigned int            component) {
                            if (component != tie.component ||
                                dof == tie_masters[t] ||
                                constraints.is_constrained(dof) ||
                                (tie.region && !tie.region(p)))
                              return;
                            constraints.add_line(dof);
                            constraints.add_entry(dof, tie_masters[t], 1.);
                            tied.add_index(dof);
                          });
        tied.compress();
      }
    constraints.close();
    homogeneous_constraints.clear();
    homogeneous_constraints.reinit(locally_relevant_dofs);
    homogeneous_constraints.merge(hanging_node_constraints);
    for (const auto &[dof, value] : dirichlet_values)
      homogeneous_constraints.add_line(dof);
    for (unsigned int t = 0; t < ties.size(); ++t)
      for (const auto dof :
           constrained_dofs_per_condition[conditions.size() + t])
        if (dof != tie_masters[t])
          {
            homogeneous_constraints.add_line(dof);
            homogeneous_constraints.add_entry(dof, tie_masters[t], 1.);
          }
    homogeneous_constraints.close();

    // Built directly in Trilinos' compressed format: a DynamicSparsityPattern
    // would double the peak memory of this step.
    TrilinosWrappers::SparsityPattern sparsity(locally_owned_dofs,
                                               locally_owned_dofs,
                                               locally_relevant_dofs,
                                               mpi_communicator);
    DoFTools::make_sparsity_pattern(dof_handler,
                                    sparsity,
                                    constraints,
                                    false,
                                    Utilities::MPI::this_mpi_process(
                                      mpi_communicator));
    for (const DofContribution *contribution : dof_contributions)
      for (const auto &group : contribution->couplings())
        constraints.add_entries_local_to_global(group, sparsity, false);
    sparsity.compress();
    system_matrix.reinit(sparsity);
    system_rhs.reinit(locally_owned_dofs, mpi_communicator);
    newton_update.reinit(locally_owned_dofs, mpi_communicator);
  }


  void
  VolumeElasticity::build_dirichlet_constraints(
    AffineConstraints<double>                                    &target,
    const std::function<double(types::global_dof_index, double)> &value_of)
    const
  {
    target.clear();
    target.reinit(locally_relevant_dofs);
    target.merge(hanging_node_constraints);
    for (const auto &[dof, value] : dirichlet_values)
      {
        target.add_line(dof);
        target.set_inhomogeneity(dof, value_of(dof, value));
      }
    for (const auto &line : homogeneous_constraints.get_lines())
      if (!target.is_constrained(line.index))
        {
          target.add_line(line.index);
          target.add_entries(line.index, line.entries);
        }
    target.close();
  }


  void
  VolumeElasticity::build_increment_constraints()
  {
    // the rest of the way to the prescribed values on the Dirichlet dofs
    build_dirichlet_constraints(increment_constraints,
                                [this](const types::global_dof_index dof,
                                       const double                  value) {
                                  return dirichlet_scale * value -
                                         locally_relevant_solution[dof];
                                });
  }


  double
  VolumeElasticity::dirichlet_gap() const
  {
    double gap = 0;
    for (const auto &[dof, value] : dirichlet_values)
      gap = std::max(gap,
                     std::abs(dirichlet_scale * value -
                              locally_relevant_solution[dof]));
    return Utilities::MPI::max(gap, mpi_communicator);
  }


  void
  VolumeElasticity::set_dirichlet_scale(const double factor)
  {
    dirichlet_scale = factor;
    build_dirichlet_constraints(constraints,
                                [factor](const types::global_dof_index,
                                         const double value) {
                                  return factor * value;
                                });
  }


  void
  VolumeElasticity::apply_constraints_to_solution()
  {
    TrilinosWrappers::MPI::Vector owned(locally_owned_dofs, mpi_communicator);
    owned = locally_relevant_solution;
    constraints.distribute(owned);
    locally_relevant_solution = owned;
  }


  double
  VolumeElasticity::assemble_newton_system(
    const bool                                                     with_matrix,
    const std::vector<std::pair<types::global_dof_index, double>> &nodal_forces,
    const Function<3>                                             *body_force)
  {
    TimerOutput::Scope t(timer, "assembly");
    if (with_matrix)
      {
        system_matrix = 0;
        build_increment_constraints();
      }
    system_rhs = 0;
    FEValues<3>        fe_values(mapping, fe, cell_quadrature, assembly_flags);
    const unsigned int n = fe.n_dofs_per_cell();
    FullMatrix<double> cell_matrix(n, n);
    Vector<double>     cell_residual(n), cell_u(n);
    std::vector<types::global_dof_index> dofs(n);
    unsigned int                         inverted = 0;
    // adds a block (tangent, residual r) as -r to the right-hand side
    const auto add_block =
      [&](const std::vector<types::global_dof_index> &block_dofs,
          const FullMatrix<double>                   &block_matrix,
          const Vector<double>                       &block_residual) {
        Vector<double> rhs(block_residual);
        rhs *= -1.;
        if (with_matrix)
          increment_constraints.distribute_local_to_global(
            block_matrix, rhs, block_dofs, system_matrix, system_rhs);
        else
          homogeneous_constraints.distribute_local_to_global(rhs,
                                                             block_dofs,
                                                             system_rhs);
      };
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          cell->get_dof_values(locally_relevant_solution, cell_u);
          if (!nonlinear_cell(cell,
                              fe_values,
                              cell_u,
                              body_force,
                              with_matrix,
                              cell_matrix,
                              cell_residual))
            {
              ++inverted;
              continue;
            }
          cell->get_dof_indices(dofs);
          add_block(dofs, cell_matrix, cell_residual);
        }
    for (const DofContribution *contribution : dof_contributions)
      contribution->add_nonlinear(locally_relevant_solution,
                                  with_matrix,
                                  add_block);
    if (with_matrix)
      system_matrix.compress(VectorOperation::add);
    system_rhs.compress(VectorOperation::add);
    for (const auto &[dof, force] : nodal_forces)
      if (locally_owned_dofs.is_element(dof))
        system_rhs[dof] += force;
    system_rhs.compress(VectorOperation::add);
    if (Utilities::MPI::sum(inverted, mpi_communicator) > 0)
      return std::numeric_limits<double>::infinity();
    return system_rhs.l2_norm();
  }


  void
  VolumeElasticity::set_growth(
    const std::function<double(const Point<3> &, const unsigned int)> &growth)
  {
    const unsigned int n_q = cell_quadrature.size();
    growth_values.assign(mesh.triangulation().n_active_cells() * n_q, 0.);
    FEValues<3> fe_values(mapping,
                          fe,
                          cell_quadrature,
                          update_quadrature_points);
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fe_values.reinit(cell);
          for (unsigned int q = 0; q < n_q; ++q)
            {
              const double g =
                growth(fe_values.quadrature_point(q), cell->material_id());
              AssertThrow(g > -1.,
                          ExcMessage("A growth ratio g <= -1 would remove "
                                     "all the material."));
              growth_values[cell->active_cell_index() * n_q + q] = g;
            }
        }
    growth_scale = 1.;
  }


  void
  VolumeElasticity::set_growth_scale(const double scale)
  {
    growth_scale = scale;
  }


  double
  VolumeElasticity::growth_volume() const
  {
    double      volume = 0;
    FEValues<3> fe_values(mapping, fe, cell_quadrature, update_JxW_values);
    if (!growth_values.empty())
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            fe_values.reinit(cell);
            for (unsigned int q = 0; q < cell_quadrature.size(); ++q)
              volume += growth_values[cell->active_cell_index() *
                                        cell_quadrature.size() +
                                      q] *
                        fe_values.JxW(q);
          }
    return Utilities::MPI::sum(volume, mpi_communicator);
  }


  double
  VolumeElasticity::volume_change() const
  {
    FEValues<3>                      fe_values(mapping,
                          fe,
                          cell_quadrature,
                          update_gradients | update_JxW_values);
    const FEValuesExtractors::Vector displacement(0);
    std::vector<Tensor<2, 3>>        gradients(cell_quadrature.size());
    double                           change = 0;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fe_values.reinit(cell);
          fe_values[displacement].get_function_gradients(
            locally_relevant_solution, gradients);
          const bool linear =
            layers.layer(cell->material_id()).model == MaterialModel::linear;
          for (unsigned int q = 0; q < cell_quadrature.size(); ++q)
            change +=
              (linear ?
                 trace(gradients[q]) :
                 determinant(unit_symmetric_tensor<3>() + gradients[q]) - 1.) *
              fe_values.JxW(q);
        }
    return Utilities::MPI::sum(change, mpi_communicator);
  }


  LinearSolveReport
  VolumeElasticity::solve_newton_update(const double forcing,
                                        const double absolute_floor,
                                        const double acceptable_residual)
  {
    newton_update = 0;
    return solve_linear_system(newton_update,
                               increment_constraints,
                               forcing,
                               absolute_floor,
                               acceptable_residual);
  }


  TruncatedCGReport
  VolumeElasticity::solve_trust_region_update(const double radius,
                                              const double forcing,
                                              const double absolute_floor,
                                              const bool   new_tangent)
  {
    TimerOutput::Scope t(timer, "solve");
    if (new_tangent)
      setup_preconditioner();
    const double tolerance =
      std::max(std::max(parameters.tolerance, forcing) * system_rhs.l2_norm(),
               absolute_floor);
    const TruncatedCGReport report = truncated_cg(
      system_matrix,
      preconditioner,
      system_rhs,
      radius,
      tolerance,
      parameters.max_iterations,
      [this](TrilinosWrappers::MPI::Vector &v) {
        increment_constraints.set_zero(v);
      },
      newton_update);
    increment_constraints.distribute(newton_update);
    return report;
  }


  void
  VolumeElasticity::shift_tangent(const double shift)
  {
    // read the diagonal before the first add leaves the matrix uncompressed
    std::vector<std::pair<types::global_dof_index, double>> additions;
    for (const types::global_dof_index row : locally_owned_dofs)
      if (!increment_constraints.is_constrained(row))
        additions.emplace_back(row, shift * system_matrix.diag_element(row));
    for (const auto &[row, value] : additions)
      system_matrix.add(row, row, value);
    system_matrix.compress(VectorOperation::add);
  }


  double
  VolumeElasticity::newton_update_curvature() const
  {
    // with the constrained entries zeroed, du . K du is the quadratic form
    // of the condensed tangent
    TrilinosWrappers::MPI::Vector du(newton_update), K_du(newton_update);
    increment_constraints.set_zero(du);
    system_matrix.vmult(K_du, du);
    const double norm = du * du;
    return norm > 0 ? (du * K_du) / norm : 0.;
  }


  std::string
  VolumeElasticity::describe_newton_update() const
  {
    TrilinosWrappers::MPI::Vector du(newton_update);
    increment_constraints.set_zero(du);
    return describe_displacement(du);
  }


  std::string
  VolumeElasticity::describe_displacement(
    const TrilinosWrappers::MPI::Vector &du) const
  {
    std::map<types::global_dof_index, Point<3>> support_points;
    DoFTools::map_dofs_to_support_points(mapping, dof_handler, support_points);
    // over the nodes, w = |du|^2 at the node: sums of w, w r, w r^2, w z,
    // w z^2 and of the squares of the radial, hoop and vertical components
    std::vector<double> sums(8, 0.);
    // the largest nodal |du| and where it is
    std::vector<double>                  largest(4, 0.);
    std::vector<types::global_dof_index> cell_dofs(fe.n_dofs_per_cell());
    std::set<types::global_dof_index>    visited;
    const unsigned int n_nodes = fe.base_element(0).n_dofs_per_cell();
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          cell->get_dof_indices(cell_dofs);
          for (unsigned int k = 0; k < n_nodes; ++k)
            {
              std::array<types::global_dof_index, 3> dofs;
              for (unsigned int c = 0; c < 3; ++c)
                dofs[c] = cell_dofs[fe.component_to_system_index(c, k)];
              if (!locally_owned_dofs.is_element(dofs[0]) ||
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


  double
  VolumeElasticity::residual_along_update() const
  {
    // the right-hand side is -r, with zeros on the constrained rows
    return -(system_rhs * newton_update);
  }


  void
  VolumeElasticity::store_solution()
  {
    stored_solution.reinit(locally_owned_dofs, mpi_communicator);
    stored_solution = locally_relevant_solution;
  }


  void
  VolumeElasticity::set_solution_from_stored(const double step)
  {
    TrilinosWrappers::MPI::Vector owned(stored_solution);
    owned.add(step, newton_update);
    locally_relevant_solution = owned;
  }


  void
  VolumeElasticity::restore_solution()
  {
    locally_relevant_solution = stored_solution;
  }


  TrilinosWrappers::MPI::Vector
  VolumeElasticity::get_solution() const
  {
    TrilinosWrappers::MPI::Vector owned(locally_owned_dofs, mpi_communicator);
    owned = locally_relevant_solution;
    return owned;
  }


  void
  VolumeElasticity::set_solution(const TrilinosWrappers::MPI::Vector &owned)
  {
    locally_relevant_solution = owned;
  }


  types::global_dof_index
  VolumeElasticity::master_dof(const unsigned int tie_index) const
  {
    AssertThrow(tie_index < tie_masters.size(),
                ExcMessage("No such tied condition."));
    return tie_masters[tie_index];
  }


  void
  VolumeElasticity::add_nodal_force(const types::global_dof_index dof,
                                    const double                  force)
  {
    if (locally_owned_dofs.is_element(dof))
      system_rhs[dof] += force;
    system_rhs.compress(VectorOperation::add);
  }


  double
  VolumeElasticity::dof_value(const types::global_dof_index dof) const
  {
    AssertThrow(locally_relevant_dofs.is_element(dof),
                ExcMessage("dof_value() needs a locally relevant dof."));
    return locally_relevant_solution[dof];
  }


  void
  VolumeElasticity::scale_solution(const double factor)
  {
    TrilinosWrappers::MPI::Vector owned(locally_owned_dofs, mpi_communicator);
    owned = locally_relevant_solution;
    owned *= factor;
    locally_relevant_solution = owned;
  }


  namespace
  {
    /**
     * Gradients, at unit point @p xi of a cell with Jacobian determinant
     * @p det_J there, of the three Wilson bubbles P_d = 4 xi_d (1 - xi_d)
     * taken with the centre Jacobian @p J0 (Taylor's modification:
     * (det J0 / det J) J0^{-T} grad_xi P_d), so that they integrate to zero
     * over the cell and the element passes the patch test when distorted.
     */
    std::array<Tensor<1, 3>, 3>
    incompatible_mode_gradients(const Tensor<2, 3> &J0,
                                const Point<3>     &xi,
                                const double        det_J)
    {
      const Tensor<2, 3>          J0_inverse_transpose = transpose(invert(J0));
      const double                ratio = determinant(J0) / det_J;
      std::array<Tensor<1, 3>, 3> gradients;
      for (unsigned int d = 0; d < 3; ++d)
        {
          Tensor<1, 3> reference;
          reference[d] = 4. * (1. - 2. * xi[d]);
          gradients[d] = ratio * (J0_inverse_transpose * reference);
        }
      return gradients;
    }

    /// Jacobian of the trilinear map of a hexahedron at its centre.
    Tensor<2, 3>
    centre_jacobian(const DoFHandler<3>::active_cell_iterator &cell)
    {
      Tensor<2, 3> J;
      for (unsigned int v = 0; v < 8; ++v)
        for (unsigned int d = 0; d < 3; ++d)
          {
            // +1/4 on the vertices with xi_d = 1, -1/4 on those with 0
            const double sign = ((v >> d) & 1) ? 0.25 : -0.25;
            for (unsigned int i = 0; i < 3; ++i)
              J[i][d] += sign * cell->vertex(v)[i];
          }
      return J;
    }
  } // namespace


  void
  VolumeElasticity::assemble_cell(
    const typename DoFHandler<3>::active_cell_iterator &cell,
    FEValues<3>                                        &fe_values,
    const Function<3>                                  *body_force,
    FullMatrix<double>                                 &cell_matrix,
    Vector<double>                                     &cell_rhs) const
  {
    fe_values.reinit(cell);
    const Layer                     &layer = layers.layer(cell->material_id());
    const LinearElasticMaterial      material(layer.youngs_modulus,
                                         layer.poisson_ratio);
    const unsigned int               n_dofs = fe.n_dofs_per_cell();
    const unsigned int               n_q    = fe_values.n_quadrature_points;
    const FEValuesExtractors::Vector displacement(0);
    const bool enhanced = parameters.formulation == Formulation::enhanced;
    const bool mixed = parameters.formulation == Formulation::mixed || enhanced;
    // the strain modes: the shape functions, then (enhanced) the nine
    // incompatible modes e_c P_d, condensed out at the end
    const unsigned int n_modes = n_dofs + (enhanced ? 9 : 0);

    cell_rhs = 0;
    FullMatrix<double> matrix(n_modes, n_modes);

    // Projection space of the volumetric strain (mixed): P_{p-1} on the
    // cell, centred and scaled for conditioning.
    const unsigned int  n_p    = (parameters.degree == 1 ? 1 : 4);
    const Point<3>      centre = cell->center();
    const double        scale  = 1. / cell->diameter();
    FullMatrix<double>  mass(n_p, n_p), coupling(n_p, n_modes);
    std::vector<double> q_basis(n_p);

    std::vector<SymmetricTensor<2, 3>> eps(n_modes);
    std::vector<double>                div(n_modes);
    Vector<double>                     force(3);
    // the eigenstrain (g/3) I of growth loads the (projected) volumetric
    // strain: kappa g div_bar(phi_i) over the strain modes
    const double        kappa = material.lambda + 2. / 3. * material.mu;
    Vector<double>      growth_rhs(n_modes);
    std::vector<double> growth_moments(n_p, 0.); // int q_a g
    bool                grows = false;
    const Tensor<2, 3>  J0 = enhanced ? centre_jacobian(cell) : Tensor<2, 3>();

    for (unsigned int q = 0; q < n_q; ++q)
      {
        const double JxW = fe_values.JxW(q);
        for (unsigned int i = 0; i < n_dofs; ++i)
          {
            eps[i] = fe_values[displacement].symmetric_gradient(i, q);
            div[i] = trace(eps[i]);
          }
        if (enhanced)
          {
            const auto g =
              incompatible_mode_gradients(J0,
                                          cell_quadrature.point(q),
                                          JxW / cell_quadrature.weight(q));
            for (unsigned int d = 0; d < 3; ++d)
              for (unsigned int c = 0; c < 3; ++c)
                {
                  Tensor<2, 3> grad;
                  grad[c]                 = g[d];
                  eps[n_dofs + 3 * d + c] = symmetrize(grad);
                  div[n_dofs + 3 * d + c] = g[d][c];
                }
          }
        // 2 mu dev(eps):dev(eps) + kappa div div, kappa = lambda + 2 mu / 3;
        // the mixed formulations project the divergence instead (B-bar)
        const double kappa_q = mixed ? 0. : kappa;
        const double g       = growth_at(cell, q);
        grows                = grows || g != 0.;
        if (!mixed)
          for (unsigned int i = 0; i < n_modes; ++i)
            growth_rhs(i) += kappa * g * div[i] * JxW;
        for (unsigned int i = 0; i < n_modes; ++i)
          for (unsigned int j = 0; j <= i; ++j)
            matrix(i, j) +=
              (2. * material.mu * (eps[i] * eps[j] - div[i] * div[j] / 3.) +
               kappa_q * div[i] * div[j]) *
              JxW;

        if (body_force != nullptr)
          {
            body_force->vector_value(fe_values.quadrature_point(q), force);
            for (unsigned int i = 0; i < n_dofs; ++i)
              {
                const unsigned int c = fe.system_to_component_index(i).first;
                cell_rhs(i) += fe_values.shape_value(i, q) * force(c) * JxW;
              }
          }

        if (mixed)
          {
            const Point<3> &x = fe_values.quadrature_point(q);
            q_basis[0]        = 1.;
            for (unsigned int d = 0; d + 1 < n_p; ++d)
              q_basis[d + 1] = (x[d] - centre[d]) * scale;
            for (unsigned int a = 0; a < n_p; ++a)
              {
                for (unsigned int b = 0; b < n_p; ++b)
                  mass(a, b) += q_basis[a] * q_basis[b] * JxW;
                for (unsigned int i = 0; i < n_modes; ++i)
                  coupling(a, i) += q_basis[a] * div[i] * JxW;
                growth_moments[a] += q_basis[a] * g * JxW;
              }
          }
      }
    for (unsigned int i = 0; i < n_modes; ++i)
      for (unsigned int j = i + 1; j < n_modes; ++j)
        matrix(i, j) = matrix(j, i);

    if (mixed)
      {
        // kappa * B^T M^{-1} B: the bulk modulus on the projected divergence
        // (B-bar: the volumetric strain is replaced by its projection).
        mass.gauss_jordan();
        FullMatrix<double> m_inv_b(n_p, n_modes);
        mass.mmult(m_inv_b, coupling);
        FullMatrix<double> volumetric(n_modes, n_modes);
        coupling.Tmmult(volumetric, m_inv_b);
        matrix.add(kappa, volumetric);
        for (unsigned int i = 0; i < n_modes; ++i)
          for (unsigned int a = 0; a < n_p; ++a)
            growth_rhs(i) += kappa * m_inv_b(a, i) * growth_moments[a];
      }

    if (enhanced)
      {
        // static condensation of the incompatible modes (they carry no
        // load): K = K_uu - K_ua K_aa^{-1} K_au
        const unsigned int n_a = n_modes - n_dofs;
        FullMatrix<double> K_ua(n_dofs, n_a), K_aa(n_a, n_a);
        for (unsigned int i = 0; i < n_modes; ++i)
          for (unsigned int j = n_dofs; j < n_modes; ++j)
            (i < n_dofs ? K_ua(i, j - n_dofs) : K_aa(i - n_dofs, j - n_dofs)) =
              matrix(i, j);
        K_aa.gauss_jordan();
        FullMatrix<double> K_aa_inv_K_au(n_a, n_dofs);
        K_aa.mTmult(K_aa_inv_K_au, K_ua);
        FullMatrix<double> correction(n_dofs, n_dofs);
        K_ua.mmult(correction, K_aa_inv_K_au);
        for (unsigned int i = 0; i < n_dofs; ++i)
          for (unsigned int j = 0; j < n_dofs; ++j)
            cell_matrix(i, j) = matrix(i, j) - correction(i, j);
        if (grows)
          {
            // the condensed load f_u - K_ua K_aa^{-1} f_a
            Vector<double> f_a(n_a), K_aa_inv_f_a(n_a);
            for (unsigned int a = 0; a < n_a; ++a)
              f_a(a) = growth_rhs(n_dofs + a);
            K_aa.vmult(K_aa_inv_f_a, f_a);
            Vector<double> f_correction(n_dofs);
            K_ua.vmult(f_correction, K_aa_inv_f_a);
            for (unsigned int i = 0; i < n_dofs; ++i)
              cell_rhs(i) += growth_rhs(i) - f_correction(i);
          }
      }
    else
      {
        for (unsigned int i = 0; i < n_dofs; ++i)
          for (unsigned int j = 0; j < n_dofs; ++j)
            cell_matrix(i, j) = matrix(i, j);
        if (grows)
          for (unsigned int i = 0; i < n_dofs; ++i)
            cell_rhs(i) += growth_rhs(i);
      }

    for (const CellContribution *contribution : contributions)
      contribution->add_to_cell(cell, cell_matrix, cell_rhs);
  }


  bool
  VolumeElasticity::nonlinear_cell(
    const typename DoFHandler<3>::active_cell_iterator &cell,
    FEValues<3>                                        &fe_values,
    const Vector<double>                               &u,
    const Function<3>                                  *body_force,
    const bool                                          with_matrix,
    FullMatrix<double>                                 &cell_matrix,
    Vector<double>                                     &cell_residual) const
  {
    const Layer &layer = layers.layer(cell->material_id());
    if (layer.model == MaterialModel::linear)
      {
        // r = K u - f (the embedded contributions included)
        assemble_cell(cell, fe_values, body_force, cell_matrix, cell_residual);
        cell_residual *= -1.;
        cell_matrix.vmult_add(cell_residual, u);
        return true;
      }
    AssertThrow(parameters.formulation != Formulation::enhanced,
                ExcMessage(
                  "Elasticity/Formulation = enhanced is for the "
                  "linear material model only; use mixed with "
                  "finite-strain (corotational, neo-Hookean) layers."));
    // the shear part: neo-Hookean in the spatial (Kirchhoff) form or
    // corotational in the material (first Piola) form; the volumetric part
    // U(J) is common to both
    const bool corotational = layer.model == MaterialModel::corotational;
    const NeoHookeanMaterial   neo_hookean(layer.youngs_modulus,
                                         layer.poisson_ratio);
    const CorotationalMaterial corotated(layer.youngs_modulus,
                                         layer.poisson_ratio);
    const VolumetricEnergy    &volumetric =
      corotational ? static_cast<const VolumetricEnergy &>(corotated) :
                        static_cast<const VolumetricEnergy &>(neo_hookean);
    const bool mean_dilatation = parameters.formulation == Formulation::mixed;
    // share of U(J) at the quadrature points (stabilises the mean dilatation)
    const double beta = parameters.volumetric_stabilisation;
    fe_values.reinit(cell);
    const unsigned int n   = fe.n_dofs_per_cell();
    const unsigned int n_q = fe_values.n_quadrature_points;

    // deformation gradients and, for the mean dilatation, the cell's
    // current-to-reference volume ratio J_bar
    std::vector<Tensor<2, 3>> F(n_q, unit_symmetric_tensor<3>());
    double                    volume = 0, current_volume = 0;
    for (unsigned int q = 0; q < n_q; ++q)
      {
        for (unsigned int i = 0; i < n; ++i)
          {
            const unsigned int c = fe.system_to_component_index(i).first;
            F[q][c] += u(i) * fe_values.shape_grad_component(i, q, c);
          }
        const double J = determinant(F[q]);
        if (!(J > 0))
          return false;
        // growth: the cell's stress-free volume
        volume += (1. + growth_at(cell, q)) * fe_values.JxW(q);
        current_volume += J * fe_values.JxW(q);
      }
    const double J_bar = current_volume / volume;

    cell_matrix   = 0;
    cell_residual = 0;
    // The tangent couples dof i = (component c, base function alpha) and
    // dof j = (d, beta) by g_alpha[k] T[c][k][d][l] g_beta[l] with the
    // spatial shape gradients g and one spatial tangent T per quadrature
    // point (material, geometric and volumetric parts), so it is assembled
    // by blocks of base functions: W = g_alpha . T once per base function,
    // then a dot product of 3-vectors per entry.
    const unsigned int n_base = fe.base_element(0).n_dofs_per_cell();
    std::vector<std::array<unsigned int, 3>> dof_of(n_base);
    std::vector<unsigned int>                component(n);
    for (unsigned int i = 0; i < n; ++i)
      {
        const auto [c, alpha] = fe.system_to_component_index(i);
        component[i]          = c;
        dof_of[alpha][c]      = i;
      }
    std::vector<Tensor<1, 3>> g(n_base); // spatial shape gradients
    std::vector<Tensor<1, 3>> g_reference(n_base);
    std::vector<Tensor<3, 3>> W(n_base);
    std::vector<double>       b(n, 0.); // int J div(phi_i)
    Tensor<2, 3>              P;        // corotational
    Tensor<4, 3>              A, T;
    SymmetricTensor<2, 3>     tau;
    SymmetricTensor<4, 3>     c_iso;
    Vector<double>            force(3);
    for (unsigned int q = 0; q < n_q; ++q)
      {
        const double       JxW   = fe_values.JxW(q);
        const double       J     = determinant(F[q]);
        const Tensor<2, 3> F_inv = invert(F[q]);
        // Growth F_g = gamma^{1/3} I with the energy gamma W(F F_g^{-1}):
        // the isochoric parts depend on J^{-1/3} F only, so they are
        // scaled by gamma; the volumetric part sees J_e = J / gamma.
        const double gamma = 1. + growth_at(cell, q);
        if (corotational)
          {
            corotated.isochoric(F[q], P, A);
            P *= gamma;
            A *= gamma;
          }
        else
          {
            neo_hookean.isochoric(F[q], tau, c_iso);
            tau *= gamma;
            c_iso *= gamma;
          }
        const double J_e = J / gamma;
        const double p   = mean_dilatation ?
                             (1. - beta) * volumetric.pressure(J_bar) +
                             beta * volumetric.pressure(J_e) :
                             volumetric.pressure(J_e);
        for (unsigned int alpha = 0; alpha < n_base; ++alpha)
          {
            g_reference[alpha] =
              fe_values.shape_grad_component(dof_of[alpha][0], q, 0);
            g[alpha] = transpose(F_inv) * g_reference[alpha];
          }
        for (unsigned int i = 0; i < n; ++i)
          {
            const unsigned int ci    = component[i];
            const unsigned int alpha = fe.system_to_component_index(i).second;
            const double       div   = g[alpha][ci];
            cell_residual(i) += (corotational ? P[ci] * g_reference[alpha] :
                                                (tau * g[alpha])[ci]) *
                                JxW;
            cell_residual(i) += p * J * div * JxW;
            b[i] += J * div * JxW;
          }
        if (body_force != nullptr)
          {
            body_force->vector_value(fe_values.quadrature_point(q), force);
            for (unsigned int i = 0; i < n; ++i)
              cell_residual(i) -=
                fe_values.shape_value(i, q) * force(component[i]) * JxW;
          }
        if (!with_matrix)
          continue;

        // the spatial tangent: the corotational first-Piola tangent pushed
        // forward (g_reference = F^T g), or the neo-Hookean c_iso with the
        // geometric part of tau
        for (unsigned int c = 0; c < 3; ++c)
          for (unsigned int k = 0; k < 3; ++k)
            for (unsigned int d = 0; d < 3; ++d)
              for (unsigned int l = 0; l < 3; ++l)
                if (corotational)
                  {
                    double value = 0;
                    for (unsigned int m = 0; m < 3; ++m)
                      for (unsigned int o = 0; o < 3; ++o)
                        value += F[q][k][m] * A[c][m][d][o] * F[q][l][o];
                    T[c][k][d][l] = value;
                  }
                else
                  T[c][k][d][l] = c_iso[c][k][d][l] + (c == d ? tau[k][l] : 0.);
        // the volumetric part: p J (div_i div_j - g_i[cj] g_j[ci]) and
        // the point share of U''
        const double volumetric_point = (mean_dilatation ? beta : 1.) * J * J *
                                        volumetric.pressure_derivative(J_e) /
                                        gamma;
        for (unsigned int c = 0; c < 3; ++c)
          for (unsigned int d = 0; d < 3; ++d)
            {
              T[c][c][d][d] += p * J + volumetric_point;
              T[c][d][d][c] -= p * J;
            }
        T *= JxW;
        for (unsigned int row = 0; row < n_base; ++row)
          for (unsigned int c = 0; c < 3; ++c)
            W[row][c] = g[row] * T[c]; // [d][l]
        for (unsigned int row = 0; row < n_base; ++row)
          for (unsigned int column = 0; column < n_base; ++column)
            for (unsigned int c = 0; c < 3; ++c)
              for (unsigned int d = 0; d < 3; ++d)
                cell_matrix(dof_of[row][c], dof_of[column][d]) +=
                  W[row][c][d] * g[column];
      }
    if (mean_dilatation && with_matrix)
      {
        const double k =
          (1. - beta) * volumetric.pressure_derivative(J_bar) / volume;
        for (unsigned int i = 0; i < n; ++i)
          for (unsigned int j = 0; j < n; ++j)
            cell_matrix(i, j) += k * b[i] * b[j];
      }
    for (const CellContribution *contribution : contributions)
      contribution->add_to_cell_nonlinear(
        cell, u, with_matrix, cell_matrix, cell_residual);
    return true;
  }


  void
  VolumeElasticity::assemble(const Function<3> *body_force)
  {
    TimerOutput::Scope t(timer, "assembly");
    system_matrix = 0;
    system_rhs    = 0;

    FEValues<3>        fe_values(mapping, fe, cell_quadrature, assembly_flags);
    FullMatrix<double> cell_matrix(fe.n_dofs_per_cell(), fe.n_dofs_per_cell());
    Vector<double>     cell_rhs(fe.n_dofs_per_cell());
    std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());

    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          assemble_cell(cell, fe_values, body_force, cell_matrix, cell_rhs);
          cell->get_dof_indices(dofs);
          constraints.distribute_local_to_global(
            cell_matrix, cell_rhs, dofs, system_matrix, system_rhs);
        }
    system_matrix.compress(VectorOperation::add);
    system_rhs.compress(VectorOperation::add);
  }


  void
  VolumeElasticity::setup_preconditioner()
  {
    TrilinosWrappers::PreconditionAMG::AdditionalData data;
    data.elliptic              = true;
    data.higher_order_elements = parameters.degree > 1;
    data.smoother_sweeps       = parameters.smoother_sweeps;
    data.aggregation_threshold = parameters.aggregation_threshold;
    // One mask per component: tells ML that there are 3 PDE equations per
    // node; the null space itself is replaced below.
    std::vector<std::vector<bool>> translation_modes;
    DoFTools::extract_constant_modes(dof_handler,
                                     ComponentMask(3, true),
                                     translation_modes);
    data.constant_modes = translation_modes;

    if (!parameters.rigid_body_modes)
      {
        preconditioner.initialize(system_matrix, data);
        return;
      }

    Teuchos::ParameterList              ml_list;
    std::unique_ptr<Epetra_MultiVector> unused;
    data.set_parameters(ml_list, unused, system_matrix);

    // Six rigid-body modes evaluated at the support points of the locally
    // owned dofs: three translations and three infinitesimal rotations.
    const Epetra_Map &map = system_matrix.trilinos_matrix().DomainMap();
    near_null_space       = std::make_unique<Epetra_MultiVector>(map, 6);
    std::map<types::global_dof_index, Point<3>> support_points;
    DoFTools::map_dofs_to_support_points(mapping, dof_handler, support_points);
    unsigned int local = 0;
    for (const auto dof : locally_owned_dofs)
      {
        const Point<3>    &x = support_points.at(dof);
        const unsigned int c =
          relevant_components[locally_relevant_dofs.index_within_set(dof)];
        for (unsigned int m = 0; m < 3; ++m)
          (*near_null_space)[m][local] = (c == m ? 1. : 0.);
        // rotations about x, y, z: omega x X
        const double rot[3][3] = {{0., -x[2], x[1]},
                                  {x[2], 0., -x[0]},
                                  {-x[1], x[0], 0.}};
        for (unsigned int m = 0; m < 3; ++m)
          (*near_null_space)[3 + m][local] = rot[m][c];
        ++local;
      }
    // Three equations per support point: ML aggregates whole nodes (the
    // three components of a point are numbered consecutively).
    ml_list.set("PDE equations", 3);
    if (!parameters.smoothed_aggregation)
      ml_list.set("aggregation: damping factor", 0.);
    ml_list.set("null space: type", "pre-computed");
    ml_list.set("null space: dimension", near_null_space->NumVectors());
    ml_list.set("null space: vectors", near_null_space->Values());
    preconditioner.initialize(system_matrix, ml_list);
  }


  LinearSolveReport
  VolumeElasticity::solve()
  {
    TrilinosWrappers::MPI::Vector solution(locally_owned_dofs,
                                           mpi_communicator);
    solution                       = locally_relevant_solution; // warm start
    const LinearSolveReport report = solve_linear_system(solution, constraints);
    locally_relevant_solution      = solution;
    return report;
  }


  LinearSolveReport
  VolumeElasticity::solve_linear_system(
    TrilinosWrappers::MPI::Vector   &solution,
    const AffineConstraints<double> &solution_constraints,
    const double                     relative_tolerance,
    const double                     absolute_floor,
    const double                     acceptable_residual)
  {
    TimerOutput::Scope t(timer, "solve");
    setup_preconditioner();
    solution_constraints.set_zero(solution);
    const double rhs_norm = system_rhs.l2_norm();
    const double target =
      std::max(std::max(parameters.tolerance, relative_tolerance) * rhs_norm,
               absolute_floor);
    LinearSolveReport          report;
    SolverControl              control(parameters.max_iterations,
                          std::max(target, 1e-300),
                          false,
                          false);
    TrilinosWrappers::SolverCG cg(control);
    try
      {
        try
          {
            cg.solve(system_matrix, solution, system_rhs, preconditioner);
          }
        catch (const SolverControl::NoConvergence &)
          {
            throw;
          }
        catch (const ExceptionBase &)
          {
            // CG breaks down on an indefinite matrix (a finite-strain
            // tangent past a stability limit): GMRES does not need
            // definiteness
            solution_constraints.set_zero(solution);
            TrilinosWrappers::SolverGMRES gmres(
              control,
              TrilinosWrappers::SolverGMRES::AdditionalData(false, 200));
            gmres.solve(system_matrix, solution, system_rhs, preconditioner);
          }
      }
    catch (const SolverControl::NoConvergence &e)
      {
        // the solver's last iterate stays in the solution
        report.reached_target = false;
        if (!(e.last_residual <= acceptable_residual))
          {
            std::ostringstream message;
            message << "CG did not converge in " << e.last_step
                    << " iterations (residual " << std::scientific
                    << std::setprecision(2) << e.last_residual << ", target "
                    << control.tolerance()
                    << "); raise Elasticity/Linear solver/Max iterations or "
                       "check the model.";
            AssertThrow(false, ExcMessage(message.str()));
          }
      }
    solution_constraints.distribute(solution);

    report.iterations     = control.last_step();
    report.final_residual = control.last_value();
    return report;
  }


  Tensor<1, 3>
  VolumeElasticity::reaction(const unsigned int condition_index,
                             const Function<3> *body_force) const
  {
    AssertThrow(condition_index < constrained_dofs_per_condition.size(),
                ExcMessage("No such Dirichlet condition."));
    // Virtual work of the residual r = K u - f (unconstrained cell
    // contributions) against a unit field w on the condition's dofs,
    // extended to the hanging nodes that depend on them. w vanishes on all
    // other dofs, so only the cells that touch its support contribute.
    TrilinosWrappers::MPI::Vector unit(locally_owned_dofs, mpi_communicator);
    for (const auto dof : constrained_dofs_per_condition[condition_index])
      if (locally_owned_dofs.is_element(dof))
        unit[dof] = 1.;
    unit.compress(VectorOperation::insert);
    hanging_node_constraints.distribute(unit);
    TrilinosWrappers::MPI::Vector weight(locally_owned_dofs,
                                         locally_relevant_dofs,
                                         mpi_communicator);
    weight = unit;

    FEValues<3>        fe_values(mapping, fe, cell_quadrature, assembly_flags);
    const unsigned int n = fe.n_dofs_per_cell();
    FullMatrix<double> cell_matrix(n, n);
    Vector<double>     cell_u(n), cell_r(n), cell_w(n);
    Tensor<1, 3>       force;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          cell->get_dof_values(weight, cell_w);
          if (cell_w.linfty_norm() == 0.)
            continue;
          // r = f_int(u) - f_ext (K u - f for linear layers)
          cell->get_dof_values(locally_relevant_solution, cell_u);
          nonlinear_cell(
            cell, fe_values, cell_u, body_force, false, cell_matrix, cell_r);
          for (unsigned int i = 0; i < n; ++i)
            force[fe.system_to_component_index(i).first] +=
              cell_r(i) * cell_w(i);
        }
    if (!dof_contributions.empty())
      {
        // the blocks' residuals on the condition's dofs (e.g. contact
        // forces on the punch), by the component of each dof
        for (const DofContribution *contribution : dof_contributions)
          contribution->add_nonlinear(
            locally_relevant_solution,
            false,
            [&](const std::vector<types::global_dof_index> &block_dofs,
                const FullMatrix<double> &,
                const Vector<double> &block_residual) {
              for (unsigned int k = 0; k < block_dofs.size(); ++k)
                force
                  [relevant_components[locally_relevant_dofs.index_within_set(
                    block_dofs[k])]] +=
                  block_residual(k) * weight[block_dofs[k]];
            });
      }
    return Utilities::MPI::sum(force, mpi_communicator);
  }


  std::pair<double, double>
  VolumeElasticity::compute_errors(const Function<3> &exact_solution) const
  {
    const QGauss<3> quadrature(parameters.degree + 2);
    Vector<float>   cell_errors(mesh.triangulation().n_active_cells());
    const auto      global_error = [&](const VectorTools::NormType norm) {
      VectorTools::integrate_difference(mapping,
                                        dof_handler,
                                        locally_relevant_solution,
                                        exact_solution,
                                        cell_errors,
                                        quadrature,
                                        norm);
      return VectorTools::compute_global_error(mesh.triangulation(),
                                               cell_errors,
                                               norm);
    };
    return {global_error(VectorTools::L2_norm),
            global_error(VectorTools::H1_seminorm)};
  }


  Tensor<1, 3>
  VolumeElasticity::point_value(const Point<3> &p) const
  {
    Tensor<1, 3> value;
    double       found = 0;
    try
      {
        const auto cell_and_point =
          GridTools::find_active_cell_around_point(mapping, dof_handler, p);
        if (cell_and_point.first->is_locally_owned())
          {
            const Quadrature<3> q(
              GeometryInfo<3>::project_to_unit_cell(cell_and_point.second));
            FEValues<3> fe_values(mapping, fe, q, update_values);
            fe_values.reinit(cell_and_point.first);
            std::vector<Vector<double>> values(1, Vector<double>(3));
            fe_values.get_function_values(locally_relevant_solution, values);
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


  std::string
  VolumeElasticity::write_vtu(const std::string &directory,
                              const std::string &basename,
                              const unsigned int step) const
  {
    const auto                &tria = mesh.triangulation();
    std::vector<Vector<float>> stress(6, Vector<float>(tria.n_active_cells()));
    Vector<float> mises(tria.n_active_cells()), layer(tria.n_active_cells()),
      subdomain(tria.n_active_cells());

    const QGauss<3>                    quadrature(parameters.degree + 1);
    FEValues<3>                        fe_values(mapping,
                          fe,
                          quadrature,
                          update_gradients | update_JxW_values);
    const FEValuesExtractors::Vector   displacement(0);
    std::vector<SymmetricTensor<2, 3>> eps(quadrature.size());
    static constexpr unsigned int      index[6][2] = {
           {0, 0}, {1, 1}, {2, 2}, {0, 1}, {1, 2}, {0, 2}};
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fe_values.reinit(cell);
          fe_values[displacement].get_function_symmetric_gradients(
            locally_relevant_solution, eps);
          SymmetricTensor<2, 3> mean_eps;
          double                volume = 0;
          for (unsigned int q = 0; q < quadrature.size(); ++q)
            {
              mean_eps += eps[q] * fe_values.JxW(q);
              volume += fe_values.JxW(q);
            }
          mean_eps /= volume;
          // The cell mean of the projected divergence equals the mean of
          // the divergence, so both formulations use the same formula.
          const Layer &layer_data = layers.layer(cell->material_id());
          const LinearElasticMaterial material(layer_data.youngs_modulus,
                                               layer_data.poisson_ratio);
          const SymmetricTensor<2, 3> sigma =
            material.stress(mean_eps, trace(mean_eps));
          const unsigned int k = cell->active_cell_index();
          for (unsigned int c = 0; c < 6; ++c)
            stress[c][k] = sigma[index[c][0]][index[c][1]];
          mises[k]     = von_mises(sigma);
          layer[k]     = cell->material_id();
          subdomain[k] = tria.locally_owned_subdomain();
        }

    DataOut<3> data_out;
    data_out.attach_dof_handler(dof_handler);
    const std::vector<std::string> names(3, "displacement");
    const std::vector<DataComponentInterpretation::DataComponentInterpretation>
      interpretation(3,
                     DataComponentInterpretation::component_is_part_of_vector);
    data_out.add_data_vector(locally_relevant_solution,
                             names,
                             DataOut<3>::type_dof_data,
                             interpretation);
    const char *stress_names[6] = {"stress_xx",
                                   "stress_yy",
                                   "stress_zz",
                                   "stress_xy",
                                   "stress_yz",
                                   "stress_xz"};
    for (unsigned int c = 0; c < 6; ++c)
      data_out.add_data_vector(stress[c], stress_names[c]);
    data_out.add_data_vector(mises, "von_mises");
    data_out.add_data_vector(layer, "layer");
    data_out.add_data_vector(subdomain, "subdomain");
    data_out.build_patches(mapping, parameters.degree);
    DataOutBase::VtkFlags flags;
    flags.compression_level = DataOutBase::VtkFlags::best_speed;
    data_out.set_flags(flags);
    return data_out.write_vtu_with_pvtu_record(
      directory + "/", basename, step, mpi_communicator, 4, 0);
  }
} // namespace ssc
