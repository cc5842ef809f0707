#ifndef ssc_nonlinear_forcing_term_h
#define ssc_nonlinear_forcing_term_h

#include <algorithm>

namespace ssc
{
  /**
   * The next forcing term of an inexact Newton method (the relative
   * accuracy of the next update) from the last one and the ratio of the last
   * two residual norms: Eisenstat and Walker (SIAM J. Sci. Comput. 17,
   * 1996), choice 2 with gamma = 0.9 and alpha = 2, with their safeguard
   * against a forcing term that falls faster than the convergence justifies,
   * at most @p largest.
   */
  inline double
  eisenstat_walker(const double previous_forcing,
                   const double residual_ratio,
                   const double largest)
  {
    const double gamma     = 0.9;
    double       forcing   = gamma * residual_ratio * residual_ratio;
    const double safeguard = gamma * previous_forcing * previous_forcing;
    if (safeguard > 0.1)
      forcing = std::max(forcing, safeguard);
    return std::min(forcing, largest);
  }
} // namespace ssc

#endif
