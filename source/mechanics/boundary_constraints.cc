#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature.h>

#include <deal.II/dofs/dof_tools.h>

#include <deal.II/fe/fe_values.h>

#include <limits>

#include <ssc/mechanics/boundary_constraints.h>

namespace ssc
{
  BoundaryConstraints::BoundaryConstraints(const DisplacementField &field)
    : field(field)
  {}


  void
  BoundaryConstraints::for_boundary_dofs(
    const types::boundary_id id,
    const std::function<
      void(types::global_dof_index, const Point<3> &, unsigned int)> &f) const
  {
    const FiniteElement<3> &fe = field.fe();
    const Quadrature<2>     support_points(fe.get_unit_face_support_points());
    FEFaceValues<3>         fe_face_values(field.mapping(),
                                   fe,
                                   support_points,
                                   update_quadrature_points);
    std::vector<types::global_dof_index> face_dofs(fe.n_dofs_per_face());
    for (const auto &cell : field.dof_handler().active_cell_iterators())
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
  }


  types::global_dof_index
  BoundaryConstraints::find_master(const TiedCondition &tie) const
  {
    const MPI_Comm communicator =
      field.dof_handler().get_triangulation().get_communicator();
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
    const double global_nearest = Utilities::MPI::min(nearest, communicator);
    AssertThrow(global_nearest < std::numeric_limits<double>::max(),
                ExcMessage("A tied boundary condition (rigid punch) "
                           "holds no degree of freedom: is the punch "
                           "smaller than the mesh cells?"));
    if (nearest != global_nearest)
      master = numbers::invalid_dof_index;
    return Utilities::MPI::min(master, communicator);
  }


  void
  BoundaryConstraints::setup(
    const std::vector<DirichletCondition> &conditions,
    const std::vector<TiedCondition>      &ties,
    const std::vector<std::pair<types::global_dof_index, unsigned int>> &extra)
  {
    find_relevant_dofs(ties, extra);

    hanging_node_constraints.clear();
    hanging_node_constraints.reinit(relevant);
    DoFTools::make_hanging_node_constraints(field.dof_handler(),
                                            hanging_node_constraints);
    hanging_node_constraints.close();

    AffineConstraints<double> &constraints = prescribed_constraints;
    constraints.clear();
    constraints.reinit(relevant);
    constraints.merge(hanging_node_constraints);

    // Dirichlet values at the face support points of every locally relevant
    // boundary face; the first condition that claims a dof wins.
    const types::global_dof_index n_dofs = field.dof_handler().n_dofs();
    condition_dofs.assign(conditions.size() + ties.size(), IndexSet(n_dofs));
    dirichlet_values.clear();
    add_dirichlet_conditions(conditions);
    constrain_tie_masters(conditions);
    add_ties(conditions, ties);
    constraints.close();

    make_homogeneous_constraints(conditions, ties);
    dirichlet_scale = 1.;
  }


  void
  BoundaryConstraints::find_relevant_dofs(
    const std::vector<TiedCondition>                                    &ties,
    const std::vector<std::pair<types::global_dof_index, unsigned int>> &extra)
  {
    // The master of each tie, made locally relevant everywhere so that
    // every rank can resolve u_i = u_master.
    tie_masters.clear();
    relevant = field.mesh_relevant_dofs();
    for (const TiedCondition &tie : ties)
      {
        tie_masters.push_back(find_master(tie));
        relevant.add_index(tie_masters.back());
      }
    for (const auto &[dof, component] : extra)
      relevant.add_index(dof);
    relevant.compress();
    relevant_components.assign(relevant.n_elements(), 0);
    const FiniteElement<3>              &fe = field.fe();
    std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
    for (const auto &cell : field.dof_handler().active_cell_iterators())
      if (!cell->is_artificial())
        {
          cell->get_dof_indices(dofs);
          for (unsigned int i = 0; i < dofs.size(); ++i)
            relevant_components[relevant.index_within_set(dofs[i])] =
              fe.system_to_component_index(i).first;
        }
    // a master or an extra dof may lie on cells this rank does not see
    for (const auto &[dof, component] : extra)
      relevant_components[relevant.index_within_set(dof)] = component;
    for (unsigned int t = 0; t < ties.size(); ++t)
      relevant_components[relevant.index_within_set(tie_masters[t])] =
        ties[t].component;
  }


  void
  BoundaryConstraints::add_dirichlet_conditions(
    const std::vector<DirichletCondition> &conditions)
  {
    AffineConstraints<double> &constraints = prescribed_constraints;
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
                            condition_dofs[c].add_index(dof);
                          });
        condition_dofs[c].compress();
      }
  }


  void
  BoundaryConstraints::constrain_tie_masters(
    const std::vector<DirichletCondition> &conditions)
  {
    const MPI_Comm communicator =
      field.dof_handler().get_triangulation().get_communicator();
    AffineConstraints<double> &constraints = prescribed_constraints;
    // A tie's master can be relevant on a rank that sees none of its faces
    // (find_relevant_dofs() added it), so only the ranks that do see them know
    // a Dirichlet condition on it (displacement control with the edge contact).
    // Every rank must constrain it alike: otherwise the blocks the others add
    // to its row (the contact's punch height) survive as a residual that
    // Newton's method cannot remove.
    for (const types::global_dof_index master : tie_masters)
      {
        unsigned int condition = numbers::invalid_unsigned_int;
        for (unsigned int c = 0; c < conditions.size(); ++c)
          if (condition == numbers::invalid_unsigned_int &&
              condition_dofs[c].is_element(master))
            condition = c;
        double value = condition == numbers::invalid_unsigned_int ?
                         -std::numeric_limits<double>::max() :
                         constraints.get_inhomogeneity(master);
        condition    = Utilities::MPI::min(condition, communicator);
        value        = Utilities::MPI::max(value, communicator);
        if (condition == numbers::invalid_unsigned_int ||
            constraints.is_constrained(master))
          continue;
        constraints.add_line(master);
        constraints.set_inhomogeneity(master, value);
        dirichlet_values.emplace_back(master, value);
        condition_dofs[condition].add_index(master);
      }
  }


  void
  BoundaryConstraints::add_ties(
    const std::vector<DirichletCondition> &conditions,
    const std::vector<TiedCondition>      &ties)
  {
    AffineConstraints<double> &constraints = prescribed_constraints;
    // Ties: u_i = u_master; the master counts among the tie's dofs.
    for (unsigned int t = 0; t < ties.size(); ++t)
      {
        const TiedCondition &tie  = ties[t];
        IndexSet            &tied = condition_dofs[conditions.size() + t];
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
  }


  void
  BoundaryConstraints::make_homogeneous_constraints(
    const std::vector<DirichletCondition> &conditions,
    const std::vector<TiedCondition>      &ties)
  {
    homogeneous_constraints.clear();
    homogeneous_constraints.reinit(relevant);
    homogeneous_constraints.merge(hanging_node_constraints);
    for (const auto &[dof, value] : dirichlet_values)
      homogeneous_constraints.add_line(dof);
    for (unsigned int t = 0; t < ties.size(); ++t)
      for (const auto dof : condition_dofs[conditions.size() + t])
        if (dof != tie_masters[t])
          {
            homogeneous_constraints.add_line(dof);
            homogeneous_constraints.add_entry(dof, tie_masters[t], 1.);
          }
    homogeneous_constraints.close();
  }


  types::global_dof_index
  BoundaryConstraints::master_dof(const unsigned int tie) const
  {
    AssertThrow(tie < tie_masters.size(),
                ExcMessage("No such tied condition."));
    return tie_masters[tie];
  }


  const IndexSet &
  BoundaryConstraints::dofs_of(const unsigned int condition) const
  {
    AssertThrow(condition < condition_dofs.size(),
                ExcMessage("No such boundary condition."));
    return condition_dofs[condition];
  }


  void
  BoundaryConstraints::build_dirichlet_constraints(
    AffineConstraints<double>                                    &target,
    const std::function<double(types::global_dof_index, double)> &value_of)
    const
  {
    target.clear();
    target.reinit(relevant);
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
  BoundaryConstraints::set_dirichlet_scale(const double factor)
  {
    dirichlet_scale = factor;
    build_dirichlet_constraints(prescribed_constraints,
                                [factor](const types::global_dof_index,
                                         const double value) {
                                  return factor * value;
                                });
  }


  const AffineConstraints<double> &
  BoundaryConstraints::update_from(
    const TrilinosWrappers::MPI::Vector &solution)
  {
    build_dirichlet_constraints(increment_constraints,
                                [&](const types::global_dof_index dof,
                                    const double                  value) {
                                  return dirichlet_scale * value -
                                         solution[dof];
                                });
    return increment_constraints;
  }


  double
  BoundaryConstraints::gap(const TrilinosWrappers::MPI::Vector &solution) const
  {
    double largest = 0;
    for (const auto &[dof, value] : dirichlet_values)
      largest =
        std::max(largest, std::abs(dirichlet_scale * value - solution[dof]));
    return Utilities::MPI::max(
      largest, field.dof_handler().get_triangulation().get_communicator());
  }
  void
  BoundaryConstraints::apply(DisplacementField &target) const
  {
    TrilinosWrappers::MPI::Vector owned = target.owned_solution();
    prescribed_constraints.distribute(owned);
    target.set_solution(owned);
  }
} // namespace ssc
