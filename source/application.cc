#include <deal.II/base/exceptions.h>
#include <deal.II/base/timer.h>
#include <deal.II/base/utilities.h>

#include <chrono>
#include <thread>

#include <ssc/application.h>
#include <ssc/base/user_message.h>
#include <ssc/identification/identification_scene.h>
#include <ssc/scenes/geometry_scene.h>
#include <ssc/scenes/growth_scene.h>
#include <ssc/scenes/incision_scene.h>
#include <ssc/scenes/indentation_scene.h>
#include <ssc/scenes/parameters.h>

namespace ssc
{
  namespace
  {
    const char *usage =
      "Usage: ssc FILE.prm [-s \"Section/Subsection/Name=value\"]...\n"
      "       ssc --check FILE.prm [-s ...]   parse and validate only\n"
      "       ssc --print-parameters          all parameters with defaults\n"
      "       ssc --help\n"
      "\n"
      "Runs the scene described by FILE.prm (units: mm, N, MPa, s; z out of\n"
      "the body, skin at z = 0) and writes output/<Run/Name>/: summary.json,\n"
      "parameters.prm, CSV tables, VTU/PVD fields and log.txt.\n"
      "-s overrides one parameter and may repeat, e.g.\n"
      "  ssc prm/punch.prm -s \"Mesh/Global refinements=1\"\n";


    /**
     * Reports @p message and returns the exit status 1. An error raised on
     * every rank (bad input, and every error ssc makes collective) is
     * printed once, by rank 0. An error raised on some ranks only would
     * leave the others waiting forever in their next collective call: the
     * failing ranks wait up to a deadline in a non-blocking barrier on
     * @p error_communicator (a duplicate that no other call uses); if not
     * every rank arrives, the failing rank prints the message itself and
     * aborts the whole job with status 1.
     */
    int
    report_error(const std::string &message,
                 const MPI_Comm     mpi_communicator,
                 const MPI_Comm     error_communicator,
                 std::ostream      &err)
    {
      const unsigned int rank =
        Utilities::MPI::this_mpi_process(mpi_communicator);
      if (Utilities::MPI::n_mpi_processes(mpi_communicator) > 1)
        {
          MPI_Request request;
          MPI_Ibarrier(error_communicator, &request);
          const double deadline = 30.;
          Timer        timer;
          int          all_failed = 0;
          while (!all_failed && timer.wall_time() < deadline)
            {
              MPI_Test(&request, &all_failed, MPI_STATUS_IGNORE);
              if (!all_failed)
                std::this_thread::sleep_for(std::chrono::milliseconds(10));
            }
          if (!all_failed)
            {
              err << "ssc: error: " << message << " (on rank " << rank
                  << " only; aborting the other ranks)" << std::endl;
              MPI_Abort(mpi_communicator, 1);
            }
        }
      if (rank == 0)
        err << "ssc: error: " << message << std::endl;
      return 1;
    }

    int
    run(const std::vector<std::string> &arguments,
        const MPI_Comm                  mpi_communicator,
        const MPI_Comm                  error_communicator,
        const bool                      root,
        std::ostream                   &out,
        std::ostream                   &err)
    {
      std::string              file;
      std::vector<std::string> overrides;
      bool                     check_only = false;
      try
        {
          for (unsigned int i = 0; i < arguments.size(); ++i)
            {
              const std::string &arg = arguments[i];
              if (arg == "-h" || arg == "--help")
                {
                  if (root)
                    out << usage;
                  return 0;
                }
              else if (arg == "--print-parameters")
                {
                  if (root)
                    Parameters::print_defaults(out);
                  return 0;
                }
              else if (arg == "--check")
                check_only = true;
              else if (arg == "-s")
                {
                  AssertThrow(i + 1 < arguments.size(),
                              ExcMessage("-s needs an argument "
                                         "\"Section/Name=value\"."));
                  overrides.push_back(arguments[++i]);
                }
              else if (!arg.empty() && arg[0] == '-')
                {
                  AssertThrow(false,
                              ExcMessage("Unknown option '" + arg +
                                         "' (see ssc --help)."));
                }
              else
                {
                  AssertThrow(file.empty(),
                              ExcMessage(
                                "More than one parameter file given ('" + file +
                                "' and '" + arg + "')."));
                  file = arg;
                }
            }
          AssertThrow(!file.empty(),
                      ExcMessage("No parameter file given (see ssc --help)."));

          Parameters parameters;
          parameters.read(file, overrides);
          if (check_only)
            {
              if (parameters.run.scene == SceneKind::identification)
                IdentificationScene::check_data(parameters);
              if (root)
                out << file << ": parameters are valid" << std::endl;
              return 0;
            }
          switch (parameters.run.scene)
            {
              case SceneKind::indentation:
                IndentationScene(parameters, mpi_communicator).run();
                break;
              case SceneKind::growth:
                GrowthScene(parameters, mpi_communicator).run();
                break;
              case SceneKind::geometry:
                GeometryScene(parameters, mpi_communicator).run();
                break;
              case SceneKind::identification:
                IdentificationScene(parameters, mpi_communicator).run();
                break;
              case SceneKind::incision:
                IncisionScene(parameters, mpi_communicator).run();
                break;
            }
          return 0;
        }
      catch (const ExceptionBase &e)
        {
          return report_error(user_message(e),
                              mpi_communicator,
                              error_communicator,
                              err);
        }
      catch (const std::bad_alloc &)
        {
          return report_error("out of memory: the model does not fit in this "
                              "machine's memory (see the Limits section and "
                              "coarsen the mesh or the microstructure).",
                              mpi_communicator,
                              error_communicator,
                              err);
        }
      catch (const std::exception &e)
        {
          return report_error(e.what(),
                              mpi_communicator,
                              error_communicator,
                              err);
        }
    }
  } // namespace


  int
  run_command_line(const std::vector<std::string> &arguments,
                   const MPI_Comm                  mpi_communicator,
                   std::ostream                   &out,
                   std::ostream                   &err)
  {
    const bool root = Utilities::MPI::this_mpi_process(mpi_communicator) == 0;
    // for report_error(): duplicated while every rank is here
    MPI_Comm error_communicator;
    MPI_Comm_dup(mpi_communicator, &error_communicator);
    const int status =
      run(arguments, mpi_communicator, error_communicator, root, out, err);
    MPI_Comm_free(&error_communicator);
    return status;
  }
} // namespace ssc
