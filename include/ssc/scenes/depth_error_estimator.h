#ifndef ssc_scenes_depth_error_estimator_h
#define ssc_scenes_depth_error_estimator_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/mpi.h>

#include <memory>
#include <string>

#include <ssc/mechanics/elastic_system.h>
#include <ssc/scenes/parameters.h>

namespace ssc
{
  /**
   * How an indentation run estimates the discretisation error of its depth
   * at each prescribed force (Punch/Depth error estimate): the interface
   * the scene calls, so that it records, prints and writes every estimate
   * the same way (depth_error_estimate_mm, depth_uncertainty_mm,
   * depth_uncertainty_method, depth_uncertainty_dofs in summary.json).
   */
  class DepthErrorEstimator
  {
  public:
    virtual ~DepthErrorEstimator() = default;

    /// The estimator that @p parameters ask for, built on
    /// @p mpi_communicator; nullptr for Punch/Depth error estimate = none.
    static std::unique_ptr<DepthErrorEstimator>
    create(const Parameters &parameters, const MPI_Comm mpi_communicator);

    /// Work before the scene's load path, reported on @p pcout
    /// (collective); by default none.
    virtual void
    prepare(ConditionalOStream &pcout);

    /// The estimated error (mm: the converged depth minus @p depth) of the
    /// scene's depth @p depth at load step @p step, force @p force (N),
    /// with @p system in its converged state; NaN where there is none
    /// (failure_reason() says why) (collective).
    virtual double
    error(const ElasticSystem &system,
          const unsigned int   step,
          const double         force,
          const double         depth) = 0;

    /// Why the last error() gave no estimate (empty if it did).
    const std::string &
    failure_reason() const
    {
      return failure;
    }

    /// What the estimate is, in a few words, for summary.json and the
    /// plot's legend.
    virtual std::string
    method() const = 0;

    /// The DoFs of the second discretisation the estimate solves.
    virtual types::global_dof_index
    n_dofs() = 0;

  protected:
    std::string failure;
  };
} // namespace ssc

#endif
