#ifndef ssc_mechanics_elastic_system_h
#define ssc_mechanics_elastic_system_h

#include <deal.II/base/function.h>
#include <deal.II/base/timer.h>

#include <deal.II/lac/trilinos_vector.h>

#include <utility>
#include <vector>

#include <ssc/materials/layer_materials.h>
#include <ssc/materials/quadrature_history.h>
#include <ssc/mechanics/boundary_constraints.h>
#include <ssc/mechanics/displacement_field.h>
#include <ssc/mechanics/elasticity_parameters.h>
#include <ssc/mechanics/growth_field.h>
#include <ssc/mechanics/system_assembler.h>
#include <ssc/mechanics/tangent_system.h>
#include <ssc/mechanics/volume_kernel.h>
#include <ssc/mesh/background_mesh.h>

namespace ssc
{
  /// The external loads of the mechanics: point loads (dof, N) and a body
  /// force (N/mm^3, none if null).
  struct Loads
  {
    std::vector<std::pair<types::global_dof_index, double>> nodal_forces;
    const Function<3> *body_force = nullptr;
  };

  /**
   * The mechanical system of the layered volume: the displacement field,
   * its constraints, the growth field, the layers' laws and their history,
   * and the one assembly loop, wired together. It assembles the residual
   * r = f_int(u) - f_ext (as the right-hand side -r) and the tangent at the
   * current displacement into its TangentSystem, which solves for updates;
   * Newton's method (nonlinear/) drives the two through ElasticProblem, the
   * linear problem is the single update of solve_linear(). Times its work
   * as "assembly".
   */
  class ElasticSystem
  {
  public:
    /// The system of the layers' laws @p materials (indexed by the cells'
    /// material_id) on @p mesh; long linear solves report
    /// their progress on @p progress (if given).
    ElasticSystem(const BackgroundMesh       &mesh,
                  LayerMaterials              materials,
                  const ElasticityParameters &parameters,
                  TimerOutput                &timer,
                  ConditionalOStream         *progress = nullptr);

    const DisplacementField &
    field() const
    {
      return displacement;
    }

    DisplacementField &
    field()
    {
      return displacement;
    }

    /// The constraints (non-const: scenes scale the prescribed values).
    BoundaryConstraints &
    constraints()
    {
      return boundary_constraints;
    }

    GrowthField &
    growth()
    {
      return growth_field;
    }

    const GrowthField &
    growth() const
    {
      return growth_field;
    }

    const LayerMaterials &
    materials() const
    {
      return layer_materials;
    }

    /// The pre-tension as a load: the pre-tensioned layers at the fraction
    /// @p f of their prestretch (LayerMaterials::set_prestretch_fraction()).
    void
    set_prestretch_fraction(const double f)
    {
      layer_materials.set_prestretch_fraction(f);
    }

    /// The time (s) of the state solved next: the visco-elastic layers
    /// relax over the step from the last accepted state's time to @p t.
    /// Without it (every scene without time) the time stays 0 and the
    /// laws answer instantly. Set it with each step's load.
    void
    set_time(const double t)
    {
      solved_time = t;
      point_history.set_time_step(t - accepted_time);
    }

    /// The laws' history per quadrature point (visco-elastic layers).
    const QuadratureHistory &
    history() const
    {
      return point_history;
    }

    /// Adds @p contribution (e.g. embedded septa) to every cell assembly
    /// from now on; it must outlive this object.
    void
    attach(const CellContribution &contribution);

    /// Adds @p contribution (e.g. punch contact) to the sparsity pattern and
    /// the assemblies; attach before setup(). It is told of every converged
    /// load increment (accept_state()).
    void
    attach(DofContribution &contribution);

    /// The current state solves the load increment: the attached dof
    /// contributions' history and the laws' quadrature-point history move
    /// on to it, unless one of them asks for
    /// the increment to be solved again (false; see
    /// NonlinearProblem::accept_state()).
    bool
    accept_state();

    /// The load increment is abandoned: the attached dof contributions and
    /// the laws' history go back to their last accepted increment
    /// (NonlinearProblem::
    /// reject_state()).
    void
    reject_state();

    /**
     * The residual r = f_int(u) - f_ext of the cells and dof contributions
     * at every dof (locally owned entries), before any boundary condition,
     * with the hanging nodes' entries distributed to the dofs they depend
     * on: on a prescribed or tied dof it is the force (N) the body exerts
     * on that condition there (collective).
     */
    TrilinosWrappers::MPI::Vector
    nodal_residual();

    /// Constraints, sparsity pattern and matrix for @p conditions and @p
    /// ties (after the field's dofs are distributed).
    void
    setup(const std::vector<DirichletCondition> &conditions,
          const std::vector<TiedCondition>      &ties = {});

    Loads &
    loads()
    {
      return external_loads;
    }

    /**
     * Assembles the right-hand side -r at the current solution and, with
     * @p with_tangent, the tangent; the right-hand side of the tangent
     * system then also takes the Dirichlet dofs the rest of the way to their
     * prescribed values. Returns the l2 norm of the right-hand side over the
     * unconstrained dofs, or infinity if a cell is inverted.
     */
    double
    assemble(const bool with_tangent);

    /**
     * Reaction force (N) on the dofs held by condition @p condition (see
     * BoundaryConstraints::setup()): the residual of the cells and dof
     * contributions, summed with the weights of a unit field on those dofs
     * (virtual work; consistent with hanging nodes). This is the force the
     * body exerts against the condition; the force applied by it is its
     * negative.
     */
    Tensor<1, 3>
    reaction(const unsigned int condition);

    /// The assembled tangent system and its solvers.
    TangentSystem &
    tangent_system()
    {
      return tangent;
    }

  private:
    /// Material::check_point() at every quadrature point (collective): a
    /// law's field undefined somewhere stops the run with its message.
    void
    check_laws_at_quadrature_points() const;

    const ElasticityParameters &parameters;
    TimerOutput                &timer;
    LayerMaterials              layer_materials;
    /// History of the laws that keep some, committed with each accepted
    /// load increment and restored when one is abandoned.
    QuadratureHistory   point_history;
    DisplacementField   displacement;
    BoundaryConstraints boundary_constraints;
    GrowthField         growth_field;
    VolumeKernel        kernel;
    SystemAssembler     assembler;
    TangentSystem       tangent;
    Loads               external_loads;
    /// the time of the state being solved and of the last accepted one (s)
    double solved_time = 0, accepted_time = 0;
    /// the attached dof contributions, told of converged increments
    std::vector<DofContribution *> dof_contributions;
  };


  /// The linear problem (small strain): assembles @p system at its current
  /// solution, solves to the linear solver's tolerance and adds the
  /// update, which is exact for a linear problem.
  LinearSolveReport
  solve_linear(ElasticSystem &system);
} // namespace ssc

#endif
