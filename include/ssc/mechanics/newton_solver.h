#ifndef ssc_mechanics_newton_solver_h
#define ssc_mechanics_newton_solver_h

#include <deal.II/base/conditional_ostream.h>

#include <ssc/mechanics/newton_parameters.h>
#include <ssc/mechanics/volume_elasticity.h>

#include <functional>
#include <string>
#include <utility>
#include <vector>

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

  /// How the load parameter of NewtonSolver::follow() enters the problem.
  enum class LoadDependence
  {
    /// forces and prescribed displacements: the tangent at the start of an
    /// increment is that of the converged state, whatever the increment
    right_hand_side,
    /// growth: the tangent changes with the load parameter
    tangent
  };

  /// What following the load to one target did.
  struct LoadPathReport
  {
    unsigned int        steps             = 0; ///< converged increments
    unsigned int        cuts              = 0; ///< rejected increments
    unsigned int        newton_iterations = 0;
    unsigned int        linear_iterations = 0;
    std::vector<double> last_residuals;
  };

  /**
   * Newton's method with a line search (on the energy along the update, or
   * backtracking on the residual norm) for the volume elasticity (and what
   * is attached to it), inexact (Eisenstat-Walker) by default: the load is
   * applied
   * by the caller (prescribed values, point loads); iterations stop when
   * the residual has dropped by the relative tolerance from its value at
   * the start of the solve, or below the absolute tolerance. Inverted cells
   * count as an infinite residual, so the line search backs off from them.
   * Where the line search finds no decrease (past a stability limit the
   * tangent is indefinite and Newton's direction need not lower the
   * residual), the solve continues with the tangent shifted by a multiple
   * of its diagonal (pseudo-transient continuation) before it gives up,
   * or with trust-region steps, which follow directions of negative
   * curvature off the saddle (Nonlinear solver/Globalisation).
   */
  class NewtonSolver
  {
  public:
    NewtonSolver(VolumeElasticity       &elasticity,
                 const NewtonParameters &parameters,
                 ConditionalOStream     &pcout,
                 const bool              verbose);

    /// Solves at the current load. @p nodal_forces are point loads.
    NewtonReport
    solve(const std::vector<std::pair<types::global_dof_index, double>>
            &nodal_forces = {});

    /**
     * Follows the load parameter from @p from to @p to in increments that
     * adapt: a failed Newton solve restores the last converged state and
     * halves the increment (an error once it falls below the minimum
     * fraction of the whole path), easy steps (at most easy_iterations
     * Newton iterations) let it grow by the growth factor; more than
     * max_increments increments (converged or cut) are an error too, so
     * that a solve crawling in tiny increments stops. @p apply_load
     * sets the load for a parameter value and returns the point loads.
     * @p increment is the first increment and returns the last accepted one.
     * Where the load enters the right-hand side only (@p load_dependence),
     * a linear solver failing on an increment's first update is an error
     * at once: a smaller increment has the same tangent.
     */
    LoadPathReport
    follow(const double from,
           const double to,
           double      &increment,
           const std::function<
             std::vector<std::pair<types::global_dof_index, double>>(double)>
                               &apply_load,
           const LoadDependence load_dependence);

  private:
    /// What a line search found: whether a step is accepted, the step and
    /// the residual norm there (the solution is left at that step).
    struct LineSearchResult
    {
      bool   accepted;
      double step;
      double residual;
    };

    /// Backtracking (halving) until the residual norm decreases.
    LineSearchResult
    residual_line_search(
      const double residual,
      const double target,
      const std::vector<std::pair<types::global_dof_index, double>>
        &nodal_forces);

    /// A step near the minimum of the energy along the update, from the
    /// slope r.du alone (the loads, contact and embedded laws are
    /// conservative); not accepted if the update does not descend.
    LineSearchResult
    energy_line_search(
      const double target,
      const std::vector<std::pair<types::global_dof_index, double>>
        &nodal_forces);

    /// What one trust-region iteration did.
    struct TrustRegionStep
    {
      bool              accepted;
      double            residual; ///< at the accepted step
      double            ratio;    ///< actual / predicted energy decrease
      TruncatedCGReport update;
    };

    /**
     * A trust-region iteration at the assembled tangent and residual: the
     * step from truncated_cg() within @p radius (<= 0: the preconditioned
     * gradient's norm), the energy decrease along it integrated from the
     * slopes r.p at 0, 1/2 and 1 (Simpson's rule, exact for a cubic
     * energy) against the model's prediction, the radius updated from
     * their ratio (Nocedal and Wright, algorithm 4.1); a rejected step
     * restores the solution. Without @p new_tangent the preconditioner of
     * the last step is reused (the same tangent, after a rejected step).
     */
    TrustRegionStep
    trust_region_step(
      double      &radius,
      const double forcing,
      const double target,
      const bool   new_tangent,
      const std::vector<std::pair<types::global_dof_index, double>>
        &nodal_forces);

    /// The next forcing term (relative accuracy of the next update) from
    /// the last one and the ratio of the last two residual norms.
    double
    eisenstat_walker(const double previous_forcing,
                     const double residual_ratio) const;

    VolumeElasticity       &elasticity;
    const NewtonParameters &parameters;
    ConditionalOStream     &pcout;
    const bool              verbose;
  };
} // namespace ssc

#endif
