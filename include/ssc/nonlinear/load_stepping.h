#ifndef ssc_nonlinear_load_stepping_h
#define ssc_nonlinear_load_stepping_h

#include <deal.II/base/conditional_ostream.h>

#include <functional>
#include <vector>

#include <ssc/nonlinear/newton_parameters.h>
#include <ssc/nonlinear/newton_solver.h>
#include <ssc/nonlinear/nonlinear_problem.h>

namespace ssc
{
  /// How the load parameter enters the problem.
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
   * Adaptive load stepping: follows a load parameter from one value to
   * another in increments, each solved by Newton's method. A failed solve
   * restores the last converged state and halves the increment (an error
   * once it falls below Minimum increment of the whole path); easy
   * increments (at most Easy iterations) let it grow by Growth factor; more
   * than Max increments increments (converged or cut) are an error too, so
   * that a solve crawling in tiny increments stops. Each increment starts
   * from a secant predictor (Nonlinear solver/Predictor), the last
   * converged increment scaled to this one, kept across calls of follow(),
   * where it lowers the residual.
   */
  class LoadStepper
  {
  public:
    /// Solves each increment with @p newton (and its problem, parameters
    /// and progress stream).
    explicit LoadStepper(NewtonSolver &newton)
      : newton(newton)
    {}

    /**
     * Follows the load from @p from to @p to; @p apply_load sets the load
     * of a parameter value on the problem. @p increment is the first
     * increment and returns the last accepted one. Where the load enters the
     * right-hand side only (@p dependence), a linear solver failing on an
     * increment's first update is an error at once: a smaller increment has
     * the same tangent.
     */
    LoadPathReport
    follow(const double                       from,
           const double                       to,
           double                            &increment,
           const std::function<void(double)> &apply_load,
           const LoadDependence               dependence);

  private:
    /// With Predictor = extrapolation: moves the state, at @p position
    /// with the load of @p next applied, along the last converged
    /// increment scaled to this one; undone where that inverts a cell and,
    /// under loads alone (no prescribed value moved), unless it lowers the
    /// residual norm: where the response stiffens or snaps, the
    /// extrapolated state can be further from equilibrium than the
    /// converged one. Returns whether the state moved.
    bool
    predict(const NonlinearProblem::VectorType &converged,
            const double                        position,
            const double                        next);

    NewtonSolver &newton;
    /// the change of the state over the last converged increment, and
    /// that increment's load
    NonlinearProblem::VectorType last_change;
    double                       last_load_increment = 0.;
  };
} // namespace ssc

#endif
