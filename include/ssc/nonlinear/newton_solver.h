#ifndef ssc_nonlinear_newton_solver_h
#define ssc_nonlinear_newton_solver_h

#include <deal.II/base/conditional_ostream.h>

#include <string>
#include <vector>

#include <ssc/nonlinear/newton_parameters.h>
#include <ssc/nonlinear/nonlinear_problem.h>

namespace ssc
{
  /// What one Newton solve did.
  struct NewtonReport
  {
    bool                converged         = false;
    unsigned int        iterations        = 0;
    unsigned int        linear_iterations = 0;
    std::vector<double> residuals; ///< l2 norm before each iteration
    std::string         failure;   ///< why it did not converge
    /// the linear solver failed on the first update (the tangent of the
    /// state the increment starts from)
    bool linear_failure_at_start = false;
  };

  /**
   * Newton's method for a NonlinearProblem at its current load, inexact
   * (Eisenstat-Walker) by default, with a globalisation (Nonlinear
   * solver/Globalisation): a line search on the energy along the update
   * (or backtracking on the residual norm), and where it finds no decrease
   * (past a stability limit the tangent is indefinite and Newton's
   * direction need not lower the residual) either the pseudo-transient
   * continuation, the tangent shifted by a multiple of its diagonal, or
   * trust-region steps, which follow directions of negative curvature off
   * the saddle. Iterations stop when the residual has dropped by the
   * relative tolerance from the scale of the load, or below the absolute
   * tolerance; while prescribed values are still to be reached, the
   * residual says nothing and every update is a whole Newton step.
   */
  class NewtonSolver
  {
  public:
    NewtonSolver(NonlinearProblem       &problem,
                 const NewtonParameters &parameters,
                 ConditionalOStream     &pcout,
                 const bool              verbose);

    /// Solves at the current load.
    NewtonReport
    solve();

    NonlinearProblem &
    get_problem() const
    {
      return problem;
    }

    const NewtonParameters &
    get_parameters() const
    {
      return parameters;
    }

    /// The progress stream, and whether iterations are reported on it.
    ConditionalOStream &
    progress() const
    {
      return pcout;
    }

    bool
    reports_iterations() const
    {
      return verbose;
    }

  private:
    /// The state of one solve.
    struct Iteration;

    /// How an iteration ended: a step was taken, the loop goes on without
    /// one (a rejected trial, a switch of method), or the solve failed.
    enum class Outcome
    {
      step,
      retry,
      failed
    };

    /// A trust-region step.
    Outcome
    trust_region_iteration(Iteration &it);

    /// A linear solve for the update, then a continuation or a Newton step
    /// along it.
    Outcome
    update_iteration(Iteration &it);

    /// A step of the pseudo-transient continuation along the update.
    Outcome
    continuation_iteration(Iteration &it);

    /// A Newton step along the update with the line search; where it finds
    /// no decrease, the switch to the continuation or the trust region.
    Outcome
    newton_iteration(Iteration &it);

    /// The line search found no decrease: retry accurately, switch the
    /// globalisation or fail.
    Outcome
    line_search_failed(Iteration &it, const double trial);

    /// Whether the continuation or trust-region steps have used up their
    /// iterations.
    bool
    continuation_exhausted(const Iteration &it) const;

    NonlinearProblem       &problem;
    const NewtonParameters &parameters;
    ConditionalOStream     &pcout;
    const bool              verbose;
  };
} // namespace ssc

#endif
