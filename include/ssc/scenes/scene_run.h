#ifndef ssc_scenes_scene_run_h
#define ssc_scenes_scene_run_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

#include <ssc/output/run_output.h>
#include <ssc/scenes/parameters.h>

namespace ssc
{
  /**
   * What every scene does around its physics: opens output/<run name>/
   * (log, used parameters), times the phases of docs/architecture.md §7 (mesh,
   * microstructure, embedding, setup, assembly, solve, output) and fills the
   * common part of summary.json (scene, run, mpi_ranks, timings, memory).
   */
  class SceneRun
  {
  public:
    SceneRun(const Parameters  &parameters,
             const MPI_Comm     mpi_communicator,
             const std::string &scene_name);

    RunOutput &
    output()
    {
      return run_output;
    }

    ConditionalOStream &
    pcout()
    {
      return run_output.progress();
    }

    /// Progress lines that depend on timing (a long solve's iterations, a
    /// long Lloyd relaxation): the same stream, silent in test mode so that
    /// reference outputs stay deterministic.
    ConditionalOStream &
    timed_pcout()
    {
      return timed_progress;
    }

    TimerOutput &
    timer()
    {
      return phase_timer;
    }

    MPI_Comm
    communicator() const
    {
      return mpi_communicator;
    }

    /// summary.json with the keys every scene has (embedded counts and
    /// solver statistics zero until the scene sets them); the scene adds its
    /// own results. Collective: phase times are the slowest rank's.
    nlohmann::ordered_json
    summary(const types::global_dof_index  dofs,
            const types::global_cell_index cells) const;

    /// One line with the wall time per phase, the slowest rank's (not in
    /// test mode). Collective.
    void
    print_wall_times();

  private:
    /// Wall time of each phase, the slowest rank's; -1 where no rank
    /// entered the phase. Collective.
    std::vector<double>
    phase_wall_times() const;

    const Parameters  &parameters;
    MPI_Comm           mpi_communicator;
    std::string        scene_name;
    RunOutput          run_output;
    ConditionalOStream timed_progress;
    TimerOutput        phase_timer;
    Timer              total_timer;
    double             memory_at_start_MB;
  };
} // namespace ssc

#endif
