#ifndef ssc_scenes_quasi_static_driver_h
#define ssc_scenes_quasi_static_driver_h

#include <deal.II/base/conditional_ostream.h>

#include <nlohmann/json.hpp>

#include <functional>
#include <vector>

#include <ssc/mechanics/elastic_system.h>
#include <ssc/nonlinear/elastic_problem.h>
#include <ssc/nonlinear/load_stepping.h>
#include <ssc/nonlinear/newton_parameters.h>
#include <ssc/nonlinear/newton_solver.h>

namespace ssc
{
  /// What the solvers did for one load step.
  struct StepStatistics
  {
    unsigned int        linear_iterations = 0;
    unsigned int        newton_iterations = 0;
    unsigned int        increments        = 0;
    unsigned int        cuts              = 0;
    double              wall_time         = 0;
    std::vector<double> final_residuals;
  };

  /**
   * The quasi-static load path every mechanics scene takes: the system is
   * brought through increasing load parameters (targets), and after each
   * the scene measures and writes. Where every layer is small strain the
   * problem is linear: one solve for the unit load (parameter 1), each
   * target by scaling. Otherwise Newton's method with adaptive increments
   * goes from one target to the next.
   */
  class QuasiStaticDriver
  {
  public:
    QuasiStaticDriver(ElasticSystem          &system,
                      const NewtonParameters &parameters,
                      ConditionalOStream     &pcout,
                      const bool              verbose);

    /**
     * Follows @p targets (increasing, > 0); @p apply_load sets the load of
     * a parameter value on the system, @p first_increment is Newton's first
     * increment, @p dependence how the load enters the problem, and @p
     * on_step(k) is called after target k is reached.
     */
    void
    run(const std::vector<double>               &targets,
        const std::function<void(double)>       &apply_load,
        const double                             first_increment,
        const LoadDependence                     dependence,
        const std::function<void(unsigned int)> &on_step);

    /// Whether the problem is linear (every layer small strain).
    bool
    linear() const;

    const std::vector<StepStatistics> &
    statistics() const
    {
      return steps;
    }

    /// summary.json's "solver" entry: totals and per-step lists of linear
    /// and Newton iterations, load cuts, wall times and the residual history
    /// of the last increment of every step.
    nlohmann::ordered_json
    summary() const;

  private:
    ElasticSystem              &system;
    ElasticProblem              problem;
    NewtonSolver                newton;
    std::vector<StepStatistics> steps;
  };
} // namespace ssc

#endif
