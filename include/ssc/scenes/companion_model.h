#ifndef ssc_scenes_companion_model_h
#define ssc_scenes_companion_model_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>

#include <string>
#include <vector>

#include <ssc/scenes/mechanics_model.h>
#include <ssc/scenes/parameters.h>
#include <ssc/scenes/punch_loading.h>

namespace ssc
{
  /**
   * An indentation scene's model built a second time with another
   * discretisation, quietly, beside the scene: what the run's own error
   * estimates solve. Its parameters are the scene's file and overrides
   * followed by overrides of its own (the other discretisation), with no
   * fields written and no estimate of its own; its progress output is
   * silent and its phases are timed apart from the scene's, so that the
   * scene's log and timings stay the scene's.
   */
  class CompanionModel
  {
  public:
    /// The model of @p scene's parameters with @p overrides applied after
    /// the scene's own, on @p mpi_communicator (collective).
    CompanionModel(const Parameters               &scene,
                   const std::vector<std::string> &overrides,
                   const MPI_Comm                  mpi_communicator);

    const Parameters &
    parameters() const
    {
      return companion_parameters;
    }

    /// The silent stream its solvers report on.
    ConditionalOStream &
    silent_stream()
    {
      return silent;
    }

    ElasticSystem &
    system()
    {
      return model.system();
    }

    PunchLoading &
    loading()
    {
      return punch_loading;
    }

  private:
    Parameters         companion_parameters;
    ConditionalOStream silent;
    TimerOutput        timer;
    MechanicsModel     model;
    PunchLoading       punch_loading;
  };
} // namespace ssc

#endif
