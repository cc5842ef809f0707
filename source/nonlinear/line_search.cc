#include <algorithm>
#include <cmath>

#include <ssc/nonlinear/line_search.h>

namespace ssc
{
  LineSearchResult
  residual_line_search(NonlinearProblem  &problem,
                       const double       residual,
                       const double       target,
                       const unsigned int max_steps)
  {
    double step = 1., trial = 0.;
    for (unsigned int k = 0; k < max_steps; ++k, step *= 0.5)
      {
        problem.set_state_from_stored(step);
        trial = problem.residual();
        if (trial <= (1. - 1e-4 * step) * residual || trial <= target)
          return {true, step, trial};
      }
    return {false, 2. * step, trial};
  }


  LineSearchResult
  energy_line_search(NonlinearProblem  &problem,
                     const double       target,
                     const unsigned int max_steps)
  {
    // The energy along the update, phi(s) = Pi(u + s du), has the slope
    // phi'(s) = r(u + s du).du; Newton's direction descends where
    // phi'(0) = -du.K du < 0. Look for a step where the slope has shrunk
    // to half of phi'(0) in magnitude (near the minimum along the line).
    const double slope_0 = problem.slope_along_update();
    if (!(slope_0 < 0.))
      return {false, 1., 0.};
    double low = 0., slope_low = slope_0, high = 1., slope_high = 0.;
    bool   bracketed = false; // a step with phi' > 0 is known
    double step = 1., trial = 0.;
    for (unsigned int k = 0; k < max_steps; ++k)
      {
        problem.set_state_from_stored(step);
        trial = problem.residual();
        if (!std::isfinite(trial))
          {
            high      = step;
            bracketed = false;
            step      = 0.5 * (low + high);
            continue;
          }
        const double slope = problem.slope_along_update();
        if (trial <= target || std::abs(slope) <= 0.5 * std::abs(slope_0) ||
            (slope < 0. && step == 1.))
          return {true, step, trial};
        if (slope < 0.)
          {
            low       = step;
            slope_low = slope;
          }
        else
          {
            high       = step;
            slope_high = slope;
            bracketed  = true;
          }
        // regula falsi inside the bracket, kept off its ends; halving
        // towards inadmissible states
        const double width = high - low;
        if (bracketed)
          {
            const double secant =
              low - slope_low * width / (slope_high - slope_low);
            step = std::clamp(secant, low + 0.1 * width, high - 0.1 * width);
          }
        else
          step = 0.5 * (low + high);
      }
    if (low == 0.)
      return {false, step, trial};
    // the last step where the energy was still falling
    problem.set_state_from_stored(low);
    return {true, low, problem.residual()};
  }
} // namespace ssc
