#include <deal.II/base/exceptions.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <string>

#include <ssc/nonlinear/load_stepping.h>

namespace ssc
{
  LoadPathReport
  LoadStepper::follow(const double                       from,
                      const double                       to,
                      double                            &increment,
                      const std::function<void(double)> &apply_load,
                      const LoadDependence               dependence)
  {
    NonlinearProblem       &problem    = newton.get_problem();
    const NewtonParameters &parameters = newton.get_parameters();
    ConditionalOStream     &pcout      = newton.progress();
    LoadPathReport          report;
    const double            path     = to - from;
    double                  position = from;
    increment                        = std::min(increment, path);
    unsigned int increments          = 0;
    while (position < to - 1e-12 * std::abs(path))
      {
        AssertThrow(increments < parameters.max_increments,
                    ExcMessage("Newton's method: the load step from " +
                               std::to_string(from) + " to " +
                               std::to_string(to) + " has reached only " +
                               std::to_string(position) + " after " +
                               std::to_string(increments) +
                               " increments (Nonlinear solver/Max "
                               "increments): the solve crawls."));
        ++increments;
        const double next  = std::min(position + increment, to);
        const auto   start = problem.state();
        apply_load(next);
        const bool   predicted = predict(start, position, next);
        NewtonReport result    = newton.solve();
        report.newton_iterations += result.iterations;
        report.linear_iterations += result.linear_iterations;
        unsigned int iterations = result.iterations, passes = 1;
        // what the solve took as fixed (friction's normal forces) may have
        // moved too far: solve again from here with it updated
        while (result.converged && !problem.accept_state())
          {
            result = newton.solve();
            report.newton_iterations += result.iterations;
            report.linear_iterations += result.linear_iterations;
            iterations += result.iterations;
            ++passes;
            if (newton.reports_iterations())
              pcout << "  load " << std::setprecision(6) << next
                    << ": solved again with the updated history ("
                    << result.iterations << " Newton iterations)" << std::endl;
          }
        if (result.converged)
          {
            last_change = problem.state();
            last_change -= start;
            last_load_increment = next - position;
            position            = next;
            ++report.steps;
            report.last_residuals = result.residuals;
            if (newton.reports_iterations())
              pcout << "  load " << std::setprecision(6) << position << ": "
                    << iterations << " Newton iterations" << std::endl;
            if (iterations <= parameters.easy_iterations)
              increment *= parameters.growth_factor;
            continue;
          }
        // Without a predictor, the first update of an increment solves
        // with the tangent of the converged state and a right-hand side
        // that scales with the increment: if CG fails on it, it fails on
        // any smaller increment too (the absolute floors of its tolerance
        // lie far below the smallest increment allowed), and cutting would
        // only crawl.
        AssertThrow(
          !(result.linear_failure_at_start && !predicted && passes == 1 &&
            dependence == LoadDependence::right_hand_side),
          ExcMessage("Newton's method failed at load " +
                     std::to_string(position) + " (" + result.failure +
                     ") on the first update of the increment. Its "
                     "tangent is that of the converged state whatever "
                     "the increment, so a smaller increment cannot "
                     "help. (Poisson's ratios near 0.5 make the "
                     "tangent hard for the AMG-preconditioned CG.)"));
        // back to the last converged state, with half the increment
        problem.set_state(start);
        problem.reject_state();
        apply_load(position);
        ++report.cuts;
        increment *= 0.5;
        pcout << "  load increment to " << std::setprecision(6) << next
              << " rejected (" << result.failure << "), cut to " << increment
              << std::endl;
        AssertThrow(increment >= parameters.minimum_increment * std::abs(path),
                    ExcMessage("Newton's method failed at load " +
                               std::to_string(position) + " (" +
                               result.failure +
                               ") and the increment fell below Nonlinear "
                               "solver/Minimum increment."));
      }
    return report;
  }


  bool
  LoadStepper::predict(const NonlinearProblem::VectorType &converged,
                       const double                        position,
                       const double                        next)
  {
    if (newton.get_parameters().predictor != Predictor::extrapolation ||
        last_load_increment <= 0.)
      return false;
    NonlinearProblem &problem = newton.get_problem();
    // Where the increment starts without the prediction. With prescribed
    // values still to be reached its residual (of the free unknowns) does
    // not say how far it is from equilibrium: only an inverted cell then
    // drops the prediction.
    const double                 unpredicted = problem.constraint_gap() > 0. ?
                                                 std::numeric_limits<double>::infinity() :
                                                 problem.residual();
    NonlinearProblem::VectorType guess       = converged;
    guess.add((next - position) / last_load_increment, last_change);
    problem.set_state(guess);
    // false for an inverted cell (an infinite residual) too
    if (problem.residual() < unpredicted)
      return true;
    problem.set_state(converged);
    return false;
  }
} // namespace ssc
