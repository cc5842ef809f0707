#ifndef ssc_mechanics_boundary_constraints_h
#define ssc_mechanics_boundary_constraints_h

#include <deal.II/base/function.h>
#include <deal.II/base/index_set.h>

#include <deal.II/fe/component_mask.h>

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_vector.h>

#include <functional>
#include <memory>
#include <utility>
#include <vector>

#include <ssc/mechanics/displacement_field.h>

namespace ssc
{
  /**
   * A prescribed displacement on (part of) a boundary: the components in
   * @p components take the values of @p values at the support points of
   * boundary @p boundary_id that satisfy @p region (all, if empty).
   */
  struct DirichletCondition
  {
    types::boundary_id                    boundary_id;
    ComponentMask                         components;
    std::shared_ptr<const Function<3>>    values;
    std::function<bool(const Point<3> &)> region;
  };

  /**
   * The dofs of displacement component @p component on (part of) boundary
   * @p boundary_id that satisfy @p region, tied to one master dof (the one
   * of that component whose support point is nearest to @p master_near):
   * they all move together, like the surface under a rigid flat punch. A
   * force applied to the master dof is then the force on the punch, and the
   * master's value its displacement (force control).
   */
  struct TiedCondition
  {
    types::boundary_id                    boundary_id;
    unsigned int                          component;
    std::function<bool(const Point<3> &)> region;
    Point<3>                              master_near;
  };

  /**
   * The constraints on the displacement: hanging nodes, prescribed values
   * (Dirichlet conditions, scaled by a load factor) and ties. Three variants
   * serve the three uses: the prescribed values themselves (distributing a
   * solution), homogeneous ones (residuals, reactions) and those of an
   * update from the current solution, which takes the Dirichlet dofs the
   * rest of the way to their prescribed values (Newton's first update of a
   * displacement-controlled increment). Each condition remembers its dofs,
   * so that its reaction force can be computed.
   */
  class BoundaryConstraints
  {
  public:
    explicit BoundaryConstraints(const DisplacementField &field);

    /// Builds the constraints; Dirichlet conditions first claim their dofs
    /// (the first one that claims a dof wins), then the ties. Their
    /// reactions are numbered in that order (conditions, then ties). The
    /// dofs of @p extra (with their components) are made locally relevant
    /// too (see DofContribution::extra_relevant_dofs()).
    void
    setup(const std::vector<DirichletCondition> &conditions,
          const std::vector<TiedCondition>      &ties,
          const std::vector<std::pair<types::global_dof_index, unsigned int>>
            &extra = {});

    /// The mesh's locally relevant dofs, the masters of the ties, which
    /// every rank needs to resolve u_i = u_master, and the extra ones of
    /// setup().
    const IndexSet &
    relevant_dofs() const
    {
      return relevant;
    }

    /// Master dof of tie @p tie (the same on every rank).
    types::global_dof_index
    master_dof(const unsigned int tie) const;

    /// The dofs held by condition @p condition (Dirichlet conditions first,
    /// then the ties with their masters); locally relevant ones.
    const IndexSet &
    dofs_of(const unsigned int condition) const;

    /// Displacement component of the locally relevant dof @p dof.
    unsigned int
    component(const types::global_dof_index dof) const
    {
      return relevant_components[relevant.index_within_set(dof)];
    }

    /// Scales the prescribed values by @p factor (a load parameter)
    /// without rebuilding the sparsity pattern.
    void
    set_dirichlet_scale(const double factor);

    /// Sets the constrained entries of @p field's solution: prescribed
    /// values (at the current Dirichlet scale), hanging nodes and ties.
    void
    apply(DisplacementField &field) const;

    const AffineConstraints<double> &
    prescribed() const
    {
      return prescribed_constraints;
    }

    const AffineConstraints<double> &
    homogeneous() const
    {
      return homogeneous_constraints;
    }

    const AffineConstraints<double> &
    hanging_nodes() const
    {
      return hanging_node_constraints;
    }

    /// Rebuilds and returns the constraints of an update from the
    /// (ghosted) @p solution.
    const AffineConstraints<double> &
    update_from(const TrilinosWrappers::MPI::Vector &solution);

    /// The constraints of the last update_from().
    const AffineConstraints<double> &
    increment() const
    {
      return increment_constraints;
    }

    /// Largest distance (mm) of a Dirichlet dof of the (ghosted) @p
    /// solution from its prescribed value (collective).
    double
    gap(const TrilinosWrappers::MPI::Vector &solution) const;

  private:
    /// Calls f(dof, support point, component) for every dof on the locally
    /// relevant faces of boundary @p id.
    void
    for_boundary_dofs(const types::boundary_id                 id,
                      const std::function<void(types::global_dof_index,
                                               const Point<3> &,
                                               unsigned int)> &f) const;

    /// The dof nearest to the tie's master_near (smallest index on ties),
    /// agreed on by all ranks.
    types::global_dof_index
    find_master(const TiedCondition &tie) const;

    /// Finds the ties' masters, the locally relevant dofs (with @p extra)
    /// and their components.
    void
    find_relevant_dofs(
      const std::vector<TiedCondition> &ties,
      const std::vector<std::pair<types::global_dof_index, unsigned int>>
        &extra);

    /// Adds the Dirichlet conditions to the prescribed constraints and
    /// records their dofs and values (the first that claims a dof wins).
    void
    add_dirichlet_conditions(const std::vector<DirichletCondition> &conditions);

    /// Constrains each tie's master alike on every rank if a Dirichlet
    /// condition holds it on some rank.
    void
    constrain_tie_masters(const std::vector<DirichletCondition> &conditions);

    /// Adds the ties u_i = u_master to the prescribed constraints and
    /// records their dofs.
    void
    add_ties(const std::vector<DirichletCondition> &conditions,
             const std::vector<TiedCondition>      &ties);

    /// Builds the homogeneous constraints: hanging nodes, zero Dirichlet
    /// values and the ties.
    void
    make_homogeneous_constraints(
      const std::vector<DirichletCondition> &conditions,
      const std::vector<TiedCondition>      &ties);

    /// Rebuilds @p target from the hanging-node constraints, the Dirichlet
    /// dofs with the inhomogeneity @p value_of (dof, prescribed value at
    /// scale 1) and the remaining homogeneous lines (ties).
    void
    build_dirichlet_constraints(
      AffineConstraints<double>                                    &target,
      const std::function<double(types::global_dof_index, double)> &value_of)
      const;

    const DisplacementField             &field;
    IndexSet                             relevant;
    std::vector<types::global_dof_index> tie_masters;
    std::vector<unsigned char>           relevant_components;
    AffineConstraints<double>            hanging_node_constraints;
    AffineConstraints<double>            prescribed_constraints;
    AffineConstraints<double>            homogeneous_constraints;
    AffineConstraints<double>            increment_constraints;
    double                               dirichlet_scale = 1.;
    /// Prescribed values of the Dirichlet dofs for scale 1.
    std::vector<std::pair<types::global_dof_index, double>> dirichlet_values;
    std::vector<IndexSet>                                   condition_dofs;
  };
} // namespace ssc

#endif
