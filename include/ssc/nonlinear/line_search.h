#ifndef ssc_nonlinear_line_search_h
#define ssc_nonlinear_line_search_h

#include <ssc/nonlinear/nonlinear_problem.h>

namespace ssc
{
  /// What a line search found: whether a step is accepted, the step and
  /// the residual norm there (the state is left at that step).
  struct LineSearchResult
  {
    bool   accepted;
    double step;
    double residual;
  };

  /// Backtracking (halving, at most @p max_steps trials) from the stored
  /// state along the update until the residual norm decreases (Armijo) or
  /// falls below @p target.
  LineSearchResult
  residual_line_search(NonlinearProblem  &problem,
                       const double       residual,
                       const double       target,
                       const unsigned int max_steps);

  /**
   * A step near the minimum of the energy along the update, from the slope
   * r.du alone (the loads, contact and embedded laws are conservative): the
   * whole step if the energy still falls there, else regula falsi in the
   * bracket, backing off from inadmissible states; not accepted if the
   * update does not descend.
   */
  LineSearchResult
  energy_line_search(NonlinearProblem  &problem,
                     const double       target,
                     const unsigned int max_steps);
} // namespace ssc

#endif
