#include <algorithm>
#include <cmath>
#include <limits>

#include <ssc/nonlinear/trust_region.h>

namespace ssc
{
  TrustRegionStep
  trust_region_step(NonlinearProblem &problem,
                    double           &radius,
                    const double      forcing,
                    const double      target,
                    const bool        new_tangent)
  {
    TrustRegionStep result{false, 0., 0., {}};
    result.update = problem.solve_update_within(radius,
                                                {forcing, 0.1 * target, 0.},
                                                new_tangent);
    if (radius <= 0.)
      radius = result.update.gradient_norm;
    if (result.update.step_norm == 0.)
      return result;
    // Pi(u + p) - Pi(u) = integral of r(u + s p).p over s in [0, 1]
    problem.store_state();
    const double slope_0 = problem.slope_along_update();
    problem.set_state_from_stored(0.5);
    const double middle     = problem.residual();
    const double slope_half = problem.slope_along_update();
    problem.set_state_from_stored(1.);
    result.residual       = problem.residual();
    const double slope_1  = problem.slope_along_update();
    const double decrease = -(slope_0 + 4. * slope_half + slope_1) / 6.;
    // a step the model does not predict to descend (possible only with an
    // indefinite preconditioner) counts as a poor one
    result.ratio = std::isfinite(middle) && std::isfinite(result.residual) &&
                       result.update.predicted_decrease > 0. ?
                     decrease / result.update.predicted_decrease :
                     -std::numeric_limits<double>::infinity();
    if (result.ratio < 0.25)
      radius = 0.25 * std::min(radius, result.update.step_norm);
    else if (result.ratio > 0.75 && result.update.on_boundary)
      radius *= 2.;
    result.accepted = result.ratio > 0.05 ||
                      (std::isfinite(middle) && result.residual <= target);
    if (!result.accepted)
      problem.restore_state();
    return result;
  }
} // namespace ssc
