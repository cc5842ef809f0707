#include <deal.II/base/array_view.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/multithread_info.h>
#include <deal.II/base/utilities.h>

#include <algorithm>
#include <numeric>
#include <sstream>
#include <utility>

#include <ssc/scenes/scene_run.h>

namespace ssc
{
  namespace
  {
    double
    resident_memory_MB(const bool peak)
    {
      Utilities::System::MemoryStats memory;
      Utilities::System::get_memory_stats(memory);
      return (peak ? memory.VmHWM : memory.VmRSS) / 1024.;
    }

    const char            *phases[] = {"mesh",
                                       "microstructure",
                                       "embedding",
                                       "setup",
                                       "assembly",
                                       "solve",
                                       "error estimate",
                                       "output"};
    constexpr unsigned int n_phases = sizeof(phases) / sizeof(phases[0]);
  } // namespace


  SceneRun::SceneRun(const Parameters  &parameters,
                     const MPI_Comm     mpi_communicator,
                     const std::string &scene_name)
    : parameters(parameters)
    , mpi_communicator(mpi_communicator)
    , scene_name(scene_name)
    , run_output(parameters.run.output_directory + "/" + parameters.run.name,
                 mpi_communicator,
                 true)
    , timed_progress(run_output.progress().get_stream(),
                     run_output.progress().is_active() &&
                       !parameters.run.test_mode)
    // each rank times its own phases (MPI_COMM_SELF): a TimerOutput on the
    // scene's communicator would synchronise every section and, destroyed
    // while an error propagates, print a banner about the skipped
    // synchronisation before the error message; phase_wall_times() takes
    // the slowest rank instead
    , phase_timer(MPI_COMM_SELF,
                  run_output.progress(),
                  TimerOutput::never,
                  TimerOutput::wall_times)
    , total_timer(mpi_communicator, true)
    // memory of the process before any model is built (libraries, MPI):
    // benchmarks report the peak with and without it
    , memory_at_start_MB(
        Utilities::MPI::sum(resident_memory_MB(false), mpi_communicator))
  {
    std::ostringstream used;
    parameters.print_used(used);
    run_output.write_text("parameters.prm", used.str());
    pcout() << "ssc " << scene_name << " scene '" << parameters.run.name
            << "' on " << Utilities::MPI::n_mpi_processes(mpi_communicator)
            << " MPI rank(s)" << std::endl;
    if (run_output.n_removed_files() > 0 && !parameters.run.test_mode)
      pcout() << "Removed " << run_output.n_removed_files()
              << " result files of an earlier run from "
              << run_output.directory() << "/" << std::endl;
    if (run_output.n_kept_files() > 0 && !parameters.run.test_mode)
      pcout() << "Kept " << run_output.n_kept_files() << " files in "
              << run_output.directory()
              << "/ that no ssc run recorded writing (.ssc_manifest)"
              << std::endl;
  }


  std::vector<double>
  SceneRun::phase_wall_times() const
  {
    const auto local =
      phase_timer.get_summary_data(TimerOutput::total_wall_time);
    std::vector<double> wall(n_phases, -1.);
    for (unsigned int i = 0; i < n_phases; ++i)
      if (local.count(phases[i]))
        wall[i] = local.at(phases[i]);
    std::vector<double> slowest(n_phases);
    Utilities::MPI::max(make_array_view(std::as_const(wall)),
                        mpi_communicator,
                        make_array_view(slowest));
    return slowest;
  }


  nlohmann::ordered_json
  SceneRun::summary(const types::global_dof_index  dofs,
                    const types::global_cell_index cells) const
  {
    const std::vector<double> wall = phase_wall_times();
    nlohmann::ordered_json    timings;
    for (unsigned int i = 0; i < n_phases; ++i)
      timings[phases[i]] = std::max(wall[i], 0.);
    timings["total"] = total_timer.wall_time();

    nlohmann::ordered_json summary;
    summary["scene"]     = scene_name;
    summary["run"]       = parameters.run.name;
    summary["dofs"]      = dofs;
    summary["cells"]     = cells;
    summary["embedded"]  = {{"septa_triangles", 0},
                            {"ligament_segments", 0},
                            {"lobules", 0}};
    summary["mpi_ranks"] = Utilities::MPI::n_mpi_processes(mpi_communicator);
    // the cell loops' threads on each rank (the cores no rank takes)
    summary["threads_per_rank"] = MultithreadInfo::n_threads();
    summary["solver"]           = {{"linear_iterations", 0},
                                   {"linear_iterations_per_step",
                                    nlohmann::ordered_json::array()},
                                   {"newton_iterations", 0}};
    summary["timings"]          = timings;
    summary["memory_MB"] =
      Utilities::MPI::sum(resident_memory_MB(true), mpi_communicator);
    summary["memory_at_start_MB"] = memory_at_start_MB;
    // the peak over the whole run (mesh, microstructure, solver) per DoF
    summary["memory_per_dof_kB"] =
      dofs > 0 ? summary["memory_MB"].get<double>() * 1024. / dofs : 0.;
    return summary;
  }


  void
  SceneRun::print_wall_times()
  {
    if (parameters.run.test_mode)
      return;
    const std::vector<double> wall = phase_wall_times();
    pcout() << "Wall time: " << total_timer.wall_time() << " s (";
    bool first = true;
    for (unsigned int i = 0; i < n_phases; ++i)
      if (wall[i] >= 0.)
        {
          pcout() << (first ? "" : ", ") << phases[i] << ' ' << wall[i];
          first = false;
        }
    pcout() << ")" << std::endl
            << "Results in " << run_output.directory() << "/" << std::endl;
  }
} // namespace ssc
