#ifndef ssc_nonlinear_trust_region_h
#define ssc_nonlinear_trust_region_h

#include <ssc/nonlinear/nonlinear_problem.h>

namespace ssc
{
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
   * step from truncated CG within @p radius (<= 0: the preconditioned
   * gradient's norm, which it returns in @p radius), the energy decrease
   * along it integrated from the slopes r.p at 0, 1/2 and 1 (Simpson's rule,
   * exact for a cubic energy) against the model's prediction, the radius
   * updated from their ratio (Nocedal and Wright, algorithm 4.1); a
   * rejected step restores the state. @p forcing and @p target are the
   * update's relative accuracy and Newton's tolerance. Without @p
   * new_tangent the preconditioner of the last step is reused (the same
   * tangent, after a rejected step).
   */
  TrustRegionStep
  trust_region_step(NonlinearProblem &problem,
                    double           &radius,
                    const double      forcing,
                    const double      target,
                    const bool        new_tangent);
} // namespace ssc

#endif
