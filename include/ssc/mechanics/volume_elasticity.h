#ifndef ssc_mechanics_volume_elasticity_h
#define ssc_mechanics_volume_elasticity_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/function.h>
#include <deal.II/base/index_set.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/tensor.h>
#include <deal.II/base/timer.h>

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/fe/component_mask.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q.h>

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/lac/vector.h>

#include <ssc/background_mesh.h>
#include <ssc/embedding/point_locator.h>
#include <ssc/layer_stack.h>
#include <ssc/mechanics/cell_contribution.h>
#include <ssc/mechanics/dof_contribution.h>
#include <ssc/mechanics/elasticity_parameters.h>
#include <ssc/mechanics/truncated_cg.h>

#include <functional>
#include <memory>
#include <string>
#include <vector>

class Epetra_MultiVector;

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

  /// What one linear solve did.
  struct LinearSolveReport
  {
    unsigned int iterations     = 0;
    double       final_residual = 0;
    /// false if CG stopped at its iteration limit with a residual that was
    /// still acceptable (see solve_newton_update())
    bool reached_target = true;
  };

  /**
   * Small-strain elasticity of the layered volume on the background mesh:
   * FE_Q(p)^3, per-layer isotropic material (material_id = layer index),
   * standard or mixed (B-bar) volumetric part, Trilinos CG with ML AMG fed
   * with the rigid-body modes. One cell assembly routine serves the matrix,
   * the right-hand side and the residual from which reactions are computed.
   */
  class VolumeElasticity
  {
  public:
    VolumeElasticity(BackgroundMesh             &mesh,
                     const LayerStack           &layers,
                     const ElasticityParameters &parameters,
                     TimerOutput                &timer,
                     ConditionalOStream         &pcout);
    ~VolumeElasticity();

    /// Distributes the degrees of freedom.
    void
    setup_dofs();

    /// Adds @p contribution (e.g. embedded septa) to every cell assembly
    /// from now on; it must outlive this object's assemblies.
    void
    attach(const CellContribution &contribution);

    /// Adds @p contribution (e.g. punch contact) to the sparsity pattern
    /// and the Newton systems; attach before setup_system().
    void
    attach(const DofContribution &contribution);

    const Mapping<3> &
    get_mapping() const
    {
      return mapping;
    }

    const FiniteElement<3> &
    get_fe() const
    {
      return fe;
    }

    /// Displacement and its gradient at located points, on every rank
    /// (collective: each point is evaluated by the rank that owns it).
    void
    evaluate_at(const std::vector<PointLocation> &locations,
                std::vector<Tensor<1, 3>>        &displacements,
                std::vector<Tensor<2, 3>>        &gradients) const;

    /// Hanging-node, Dirichlet and tied constraints, sparsity and matrix
    /// layout.
    void
    setup_system(const std::vector<DirichletCondition> &conditions,
                 const std::vector<TiedCondition>      &ties = {});

    /// Master dof of tie @p tie_index (the same on every rank).
    types::global_dof_index
    master_dof(const unsigned int tie_index) const;

    /// Adds @p force (N) to the right-hand side at @p dof (after
    /// assemble()).
    void
    add_nodal_force(const types::global_dof_index dof, const double force);

    /// Value of the solution at @p dof, which must be locally relevant on
    /// every rank (e.g. a master dof).
    double
    dof_value(const types::global_dof_index dof) const;

    /// Scales the solution (linear problems: the response to another load
    /// of the same shape).
    void
    scale_solution(const double factor);

    /**
     * Isotropic volumetric growth: the material at reference point X takes
     * the stress-free volume (1 + s g(X)) dX, s the growth scale. At finite
     * strain F = F_e F_g with F_g = (1 + s g)^{1/3} I and the energy
     * (1 + s g) W(F_e); at small strain the eigenstrain (s g / 3) I. @p
     * growth (of the point and the cell's layer) is sampled once at the
     * assembly's quadrature points of the locally owned cells; the scale
     * starts at 1.
     */
    void
    set_growth(const std::function<double(const Point<3> &, const unsigned int)>
                 &growth);

    /// The growth scale s (a load parameter for Newton's method).
    void
    set_growth_scale(const double scale);

    /// The stress-free added volume at scale 1, integral of g (mm^3), with
    /// the assembly's quadrature (all ranks).
    double
    growth_volume() const;

    /// The change of the body's volume, the integral of det F - 1 (of
    /// div u for the linear law) over the mesh (mm^3, all ranks).
    double
    volume_change() const;

    /// @name Newton's method (finite strain; the linear law is the special
    /// case that converges in one iteration)
    /// @{

    /// Scales the prescribed (Dirichlet) values of setup_system() by
    /// @p factor, without rebuilding the sparsity pattern.
    void
    set_dirichlet_scale(const double factor);

    /// Largest distance (mm) of a Dirichlet dof from its prescribed value
    /// (after set_dirichlet_scale(), before Newton has reached it).
    double
    dirichlet_gap() const;

    /// Sets the constrained entries of the solution: prescribed values
    /// (times the Dirichlet scale), hanging nodes and ties.
    void
    apply_constraints_to_solution();

    /**
     * Assembles the residual r = f_int(u) - f_ext at the current solution:
     * system_rhs = -r over the unconstrained dofs, whose l2 norm it
     * returns, or infinity if a cell is inverted (det F <= 0). With
     * @p with_matrix it assembles the tangent instead, for the Newton
     * update: system_matrix = K and a right-hand side in which the update
     * also takes the Dirichlet dofs the rest of the way to their prescribed
     * values (so the prescribed displacement spreads through the tangent
     * instead of distorting the cells at the boundary). @p nodal_forces are
     * external point loads (dof, N).
     */
    double
    assemble_newton_system(
      const bool with_matrix,
      const std::vector<std::pair<types::global_dof_index, double>>
                        &nodal_forces = {},
      const Function<3> *body_force   = nullptr);

    /// Solves K du = -r (CG + AMG, homogeneous constraints) to the relative
    /// tolerance @p forcing (an inexact Newton method's forcing term) or the
    /// linear solver's, whichever is larger, but not below
    /// @p absolute_floor (N): near a converged state the relative target
    /// can fall below what round-off lets CG reach, while Newton only needs
    /// the update to be well inside its own tolerance. If CG reaches its
    /// iteration limit with the residual below @p acceptable_residual (N),
    /// the update is kept (it is still an inexact Newton step: the caller
    /// passes the largest forcing term times the right-hand side, or its
    /// own tolerance, which the linearised residual then already meets)
    /// instead of failing.
    LinearSolveReport
    solve_newton_update(const double forcing             = 0.,
                        const double absolute_floor      = 0.,
                        const double acceptable_residual = 0.);

    /**
     * The Newton update as a trust-region step (truncated_cg(): Steihaug-
     * Toint CG + AMG, homogeneous constraints) within @p radius in the
     * preconditioner's norm (<= 0: the preconditioned gradient's norm),
     * to the relative tolerance @p forcing (or the linear solver's) but not
     * below @p absolute_floor, as solve_newton_update(). The tangent need
     * not be positive definite. Only with the prescribed displacements
     * reached (the update must not move the Dirichlet dofs). Without
     * @p new_tangent the preconditioner of the last solve is reused (the
     * tangent has not changed since).
     */
    TruncatedCGReport
    solve_trust_region_update(const double radius,
                              const double forcing        = 0.,
                              const double absolute_floor = 0.,
                              const bool   new_tangent    = true);

    /// Adds @p shift times its own diagonal to the tangent (free rows):
    /// K + shift D is positive definite for a large enough shift where K
    /// is not, which is what the pseudo-transient continuation of the
    /// Newton solver needs past a stability limit.
    void
    shift_tangent(const double shift);

    /// du . K du / du . du for the last update du (free dofs): negative
    /// when the tangent is indefinite along it, e.g. past a stability
    /// limit of the discrete problem.
    double
    newton_update_curvature() const;

    /// Where the last update du lives (free dofs): the centre and spread
    /// of |du|^2 in radius from the z axis (the punch's) and in depth, the
    /// shares of its radial, hoop and vertical components and its largest
    /// nodal value. Printed when the tangent is indefinite along du (whose
    /// direction the negative eigenvalue then dominates), it tells which
    /// part of the model loses stability (collective).
    std::string
    describe_newton_update() const;

    /// The same description of any displacement field @p du (locally owned
    /// entries, e.g. the change of the solution over a failed increment).
    std::string
    describe_displacement(const TrilinosWrappers::MPI::Vector &du) const;

    /// r . du for the last update du and the residual r of the last
    /// assembly: the slope of the energy along du (the loads are
    /// conservative), negative where du descends.
    double
    residual_along_update() const;

    /// Remembers the current solution as the start of a line search.
    void
    store_solution();

    /// Solution = stored solution + @p step * du.
    void
    set_solution_from_stored(const double step);

    /// Restores the stored solution (a failed line search).
    void
    restore_solution();

    /// A copy of the solution (locally owned entries).
    TrilinosWrappers::MPI::Vector
    get_solution() const;

    /// Replaces the solution (locally owned entries, e.g. from
    /// get_solution()).
    void
    set_solution(const TrilinosWrappers::MPI::Vector &owned);
    /// @}

    /// Assembles matrix and right-hand side; @p body_force in N/mm^3.
    void
    assemble(const Function<3> *body_force = nullptr);

    /// Solves with CG + AMG, distributes constraints.
    LinearSolveReport
    solve();

    /**
     * Reaction force (N) on the dofs held by condition @p condition_index:
     * the residual K u - f of the unconstrained cell contributions and of
     * the attached dof contributions (e.g. punch contact), summed with
     * weights of a unit field on those dofs (virtual work; consistent with
     * hanging nodes). This is the force the body exerts against the
     * boundary condition; the force applied by it is its negative.
     */
    Tensor<1, 3>
    reaction(const unsigned int condition_index,
             const Function<3> *body_force = nullptr) const;

    /// L2 norm and H1 seminorm of u - exact.
    std::pair<double, double>
    compute_errors(const Function<3> &exact_solution) const;

    /// Writes displacement, cell stress, von Mises and layer id as
    /// VTU (+ PVTU record); returns the name of the master file.
    std::string
    write_vtu(const std::string &directory,
              const std::string &basename,
              const unsigned int step) const;

    /// Displacement at point @p p (on whichever rank owns it, then
    /// broadcast); throws if no rank finds it.
    Tensor<1, 3>
    point_value(const Point<3> &p) const;

    types::global_dof_index
    n_dofs() const
    {
      return dof_handler.n_dofs();
    }

    const DoFHandler<3> &
    get_dof_handler() const
    {
      return dof_handler;
    }

    const TrilinosWrappers::MPI::Vector &
    solution() const
    {
      return locally_relevant_solution;
    }

    /// The last assembled matrix (tangent) and right-hand side (tests).
    const TrilinosWrappers::SparseMatrix &
    get_system_matrix() const
    {
      return system_matrix;
    }

    const TrilinosWrappers::MPI::Vector &
    get_system_rhs() const
    {
      return system_rhs;
    }

  private:
    /**
     * The one nonlinear cell routine: tangent (if @p with_matrix; linear
     * layers always) and residual f_int - f_ext at the cell's displacement
     * values @p u (linear layers: K u - f from assemble_cell(); neo-Hookean
     * and corotational layers: finite strain, with the mean dilatation in
     * the mixed formulation). Returns false if det F <= 0 at a quadrature
     * point.
     */
    bool
    nonlinear_cell(const typename DoFHandler<3>::active_cell_iterator &cell,
                   FEValues<3>          &fe_values,
                   const Vector<double> &u,
                   const Function<3>    *body_force,
                   const bool            with_matrix,
                   FullMatrix<double>   &cell_matrix,
                   Vector<double>       &cell_residual) const;

    /// The one cell assembly of this physics (matrix and load vector).
    void
    assemble_cell(const typename DoFHandler<3>::active_cell_iterator &cell,
                  FEValues<3>                                        &fe_values,
                  const Function<3>  *body_force,
                  FullMatrix<double> &cell_matrix,
                  Vector<double>     &cell_rhs) const;

    void
    setup_preconditioner();

    /// CG + AMG for the current system_matrix and system_rhs into
    /// @p solution (a warm start), to @p relative_tolerance (at least the
    /// linear solver's) but not below @p absolute_floor, then the
    /// constraints applied; at the iteration limit an error unless the
    /// residual is below @p acceptable_residual (N).
    LinearSolveReport
    solve_linear_system(TrilinosWrappers::MPI::Vector   &solution,
                        const AffineConstraints<double> &solution_constraints,
                        const double relative_tolerance  = 0.,
                        const double absolute_floor      = 0.,
                        const double acceptable_residual = 0.);

    BackgroundMesh             &mesh;
    const LayerStack           &layers;
    const ElasticityParameters &parameters;
    TimerOutput                &timer;
    ConditionalOStream         &pcout;
    MPI_Comm                    mpi_communicator;

    FESystem<3>   fe;
    MappingQ<3>   mapping;
    DoFHandler<3> dof_handler;
    /// Quadrature and update flags of the one cell assembly routine.
    const QGauss<3>   cell_quadrature;
    const UpdateFlags assembly_flags;
    IndexSet          locally_owned_dofs;
    IndexSet          locally_relevant_dofs;
    /// The locally relevant dofs of the mesh, without the master dofs of
    /// ties that setup_system() adds to locally_relevant_dofs.
    IndexSet                             mesh_relevant_dofs;
    std::vector<types::global_dof_index> tie_masters;
    /// Displacement component of each locally relevant dof (ordered like
    /// locally_relevant_dofs, tie masters included).
    std::vector<unsigned char> relevant_components;

    AffineConstraints<double> hanging_node_constraints;
    AffineConstraints<double> constraints;
    /// The same constraints with zero inhomogeneities (residuals) and with
    /// the remaining Dirichlet increment (Newton updates).
    AffineConstraints<double> homogeneous_constraints;
    AffineConstraints<double> increment_constraints;
    double                    dirichlet_scale = 1.;

    void
    build_increment_constraints();
    /// Rebuilds @p target from the hanging-node constraints, the Dirichlet
    /// dofs with the inhomogeneity @p value_of (dof, prescribed value at
    /// scale 1) and the remaining homogeneous lines (ties); close()
    /// resolves the chains through hanging nodes and ties.
    void
    build_dirichlet_constraints(
      AffineConstraints<double>                                    &target,
      const std::function<double(types::global_dof_index, double)> &value_of)
      const;
    /// Prescribed values of the Dirichlet dofs for scale 1.
    std::vector<std::pair<types::global_dof_index, double>> dirichlet_values;
    TrilinosWrappers::MPI::Vector                           newton_update;
    TrilinosWrappers::MPI::Vector                           stored_solution;
    std::vector<IndexSet> constrained_dofs_per_condition;

    TrilinosWrappers::SparseMatrix      system_matrix;
    TrilinosWrappers::MPI::Vector       system_rhs;
    TrilinosWrappers::MPI::Vector       locally_relevant_solution;
    TrilinosWrappers::PreconditionAMG   preconditioner;
    std::unique_ptr<Epetra_MultiVector> near_null_space;
    /// g at the quadrature points, cell by cell (active cell index times
    /// the points per cell); empty without growth.
    std::vector<double> growth_values;
    double              growth_scale = 1.;
    /// The growth ratio s g at point @p q of @p cell (0 without growth).
    double
    growth_at(const typename DoFHandler<3>::active_cell_iterator &cell,
              const unsigned int                                  q) const
    {
      return growth_values.empty() ?
               0. :
               growth_scale * growth_values[cell->active_cell_index() *
                                              cell_quadrature.size() +
                                            q];
    }

    std::vector<const CellContribution *> contributions;
    std::vector<const DofContribution *>  dof_contributions;
  };
} // namespace ssc

#endif
