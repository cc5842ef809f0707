#include <deal.II/base/utilities.h>

#include <ssc/scenes/scene_run.h>

#include <numeric>
#include <sstream>

namespace ssc
{
  nlohmann::ordered_json
  solver_summary(const std::vector<unsigned int>        &linear_iterations,
                 const std::vector<unsigned int>        &newton_iterations,
                 const std::vector<unsigned int>        &cuts,
                 const std::vector<double>              &wall_times,
                 const std::vector<std::vector<double>> &final_residuals)
  {
    const auto total = [](const std::vector<unsigned int> &counts) {
      return std::accumulate(counts.begin(), counts.end(), 0u);
    };
    nlohmann::ordered_json solver = {
      {"linear_iterations", total(linear_iterations)},
      {"linear_iterations_per_step", linear_iterations},
      {"newton_iterations", total(newton_iterations)},
      {"newton_iterations_per_step", newton_iterations},
      {"load_cuts_per_step", cuts},
      {"wall_time_per_step", wall_times}};
    if (!final_residuals.empty())
      solver["final_residuals_per_step"] = final_residuals;
    return solver;
  }


  namespace
  {
    double
    resident_memory_MB(const bool peak)
    {
      Utilities::System::MemoryStats memory;
      Utilities::System::get_memory_stats(memory);
      return (peak ? memory.VmHWM : memory.VmRSS) / 1024.;
    }

    const char *phases[] = {"mesh",
                            "microstructure",
                            "embedding",
                            "setup",
                            "assembly",
                            "solve",
                            "output"};
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
    , phase_timer(mpi_communicator,
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
  }


  nlohmann::ordered_json
  SceneRun::summary(const types::global_dof_index  dofs,
                    const types::global_cell_index cells) const
  {
    auto wall = phase_timer.get_summary_data(TimerOutput::total_wall_time);
    nlohmann::ordered_json timings;
    for (const char *phase : phases)
      timings[phase] = wall.count(phase) ? wall[phase] : 0.;
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
    summary["solver"]    = {{"linear_iterations", 0},
                            {"linear_iterations_per_step",
                             nlohmann::ordered_json::array()},
                            {"newton_iterations", 0}};
    summary["timings"]   = timings;
    summary["memory_MB"] =
      Utilities::MPI::sum(resident_memory_MB(true), mpi_communicator);
    summary["memory_at_start_MB"] = memory_at_start_MB;
    return summary;
  }


  void
  SceneRun::print_wall_times()
  {
    if (parameters.run.test_mode)
      return;
    auto wall = phase_timer.get_summary_data(TimerOutput::total_wall_time);
    pcout() << "Wall time: " << total_timer.wall_time() << " s (";
    bool first = true;
    for (const char *phase : phases)
      if (wall.count(phase))
        {
          pcout() << (first ? "" : ", ") << phase << ' ' << wall[phase];
          first = false;
        }
    pcout() << ")" << std::endl
            << "Results in " << run_output.directory() << "/" << std::endl;
  }
} // namespace ssc
