#ifndef ssc_mechanics_tangent_system_h
#define ssc_mechanics_tangent_system_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>

#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>
#include <deal.II/lac/trilinos_vector.h>

#include <memory>

#include <ssc/linear_algebra/truncated_cg.h>
#include <ssc/mechanics/boundary_constraints.h>
#include <ssc/mechanics/displacement_field.h>
#include <ssc/mechanics/elasticity_parameters.h>
#include <ssc/mechanics/linear_solver.h>
#include <ssc/mechanics/pressure_system.h>

namespace ssc
{
  /// The last linearisation of an ElasticSystem.
  struct LinearisedSystem
  {
    /// The tangent (with the constraints of the last assembly).
    TrilinosWrappers::SparseMatrix tangent;
    /// The right-hand side -r (zero on constrained rows).
    TrilinosWrappers::MPI::Vector rhs;
    /// The last update (locally owned entries).
    TrilinosWrappers::MPI::Vector update;
  };


  /**
   * The linear half of the mechanical system: the tangent system K du = -r
   * that ElasticSystem assembles, and its solution for the update (a Krylov
   * or direct solve, the displacement-pressure block solve, or a truncated
   * CG step within a trust region). Newton's method reaches it through
   * ElasticProblem; it knows the field and its constraints only to
   * precondition and to keep the constrained entries of the update zero.
   * Times its work as "solve".
   */
  class TangentSystem
  {
  public:
    /// The tangent system of @p field with @p constraints; long solves
    /// report their progress on @p progress (if given).
    TangentSystem(const ElasticityParameters &parameters,
                  const DisplacementField    &field,
                  const BoundaryConstraints  &constraints,
                  TimerOutput                &timer,
                  ConditionalOStream         *progress = nullptr);

    /// Matrix and vectors for @p sparsity (and the pressure system of
    /// Linear solver/Method = block), after the constraints are set up.
    void
    setup(const TrilinosWrappers::SparsityPattern &sparsity);

    /// The last assembled tangent, right-hand side and update.
    LinearisedSystem &
    linearised()
    {
      return linearisation;
    }

    const LinearisedSystem &
    linearised() const
    {
      return linearisation;
    }

    /// The displacement-pressure system the assembly fills (Method =
    /// block), or null.
    PressureSystem *
    pressure_system()
    {
      return pressure.get();
    }

    /// Solves the assembled system for the update (from zero).
    LinearSolveReport
    solve_update(const SolveTarget &target);

    /// The update as a trust-region step within @p radius (see
    /// LinearSolver::solve_within()); the prescribed displacements must have
    /// been reached.
    TruncatedCGReport
    solve_update_within(const double       radius,
                        const SolveTarget &target,
                        const bool         new_preconditioner);

    /// Adds @p shift times its own diagonal to the tangent on the rows of
    /// the free unknowns (Newton's globalisation).
    void
    shift_tangent(const double shift);

    /// The linear solver, for its statistics (factorisations).
    const LinearSolver &
    solver() const
    {
      return linear_solver;
    }

  private:
    const ElasticityParameters &parameters;
    const DisplacementField    &field;
    const BoundaryConstraints  &constraints;
    TimerOutput                &timer;
    LinearSolver                linear_solver;
    /// The displacement-pressure system (Linear solver/Method = block).
    std::unique_ptr<PressureSystem> pressure;
    LinearisedSystem                linearisation;
  };
} // namespace ssc

#endif
