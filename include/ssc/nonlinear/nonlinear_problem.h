#ifndef ssc_nonlinear_nonlinear_problem_h
#define ssc_nonlinear_nonlinear_problem_h

#include <deal.II/lac/trilinos_vector.h>

#include <string>

#include <ssc/linear_algebra/truncated_cg.h>
#include <ssc/mechanics/linear_solver.h>

namespace ssc
{
  /**
   * What Newton's method needs of a problem R(u) = 0 whose residual is the
   * gradient of an energy (every law, load and contact of ssc is
   * conservative): residuals and tangents at the current state, linear
   * solves for the update, and moving the state along it. The state may be
   * inadmissible (inverted cells), which shows as an infinite residual.
   * Loads are set on the problem by the caller between solves.
   */
  class NonlinearProblem
  {
  public:
    using VectorType = TrilinosWrappers::MPI::Vector;

    virtual ~NonlinearProblem() = default;

    /// Assembles the residual at the current state; returns its norm over
    /// the free unknowns, or infinity where the state is inadmissible.
    virtual double
    residual() = 0;

    /// Assembles the tangent and the residual (the right-hand side of the
    /// update); returns the residual norm, or infinity.
    virtual double
    tangent() = 0;

    /// Norm of the right-hand side of the last assembly.
    virtual double
    rhs_norm() const = 0;

    /// The update du for the assembled tangent, to @p target.
    virtual LinearSolveReport
    solve_update(const SolveTarget &target) = 0;

    /// The update as a trust-region step within @p radius; without
    /// @p new_tangent the preconditioner of the last step is reused.
    virtual TruncatedCGReport
    solve_update_within(const double       radius,
                        const SolveTarget &target,
                        const bool         new_tangent) = 0;

    /// Adds @p shift times its own diagonal to the tangent (free rows).
    virtual void
    shift_tangent(const double shift) = 0;

    /// du . K du / du . du for the last update du (free unknowns): negative
    /// where the tangent is indefinite along it.
    virtual double
    update_curvature() const = 0;

    /// r . du for the last update and the last assembled residual: the
    /// slope of the energy along du.
    virtual double
    slope_along_update() const = 0;

    /// Remembers the current state as the start of a line search.
    virtual void
    store_state() = 0;

    /// State = stored state + @p step du.
    virtual void
    set_state_from_stored(const double step) = 0;

    /// Back to the stored state.
    virtual void
    restore_state() = 0;

    virtual VectorType
    state() const = 0;

    virtual void
    set_state(const VectorType &state) = 0;

    /// How far prescribed values still are from being reached (0 once
    /// they are).
    virtual double
    constraint_gap() const = 0;

    /// Norm of the applied point loads, the scale of the load.
    virtual double
    applied_load() const = 0;

    /// Where the last update lives, for diagnostics.
    virtual std::string
    describe_update() const = 0;

    /// Where a change of the state lives, for diagnostics.
    virtual std::string
    describe_change(const VectorType &change) const = 0;

    /**
     * The current state solves the load increment: history variables (e.g.
     * where friction sticks) move on to it and true is returned, or, if
     * quantities the solve took as fixed (friction's normal forces) have
     * changed too much, they are updated, the history stays, and false asks
     * for the increment to be solved again. True by default.
     */
    virtual bool
    accept_state()
    {
      return true;
    }

    /// The load increment is abandoned (the state goes back to the last
    /// converged one): what accept_state() updated during its passes goes
    /// back to the last accepted increment's. Nothing by default.
    virtual void
    reject_state()
    {}
  };
} // namespace ssc

#endif
