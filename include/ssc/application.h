#ifndef ssc_application_h
#define ssc_application_h

#include <deal.II/base/mpi.h>

#include <ostream>
#include <string>
#include <vector>

namespace ssc
{
  /**
   * The command line of ssc (docs/architecture.md §7):
   *   ssc FILE.prm [-s "Section/Name=value"]...   run the scene
   *   ssc --check FILE.prm [-s ...]               parse and validate only
   *   ssc --print-parameters                      all parameters, documented
   *   ssc --help
   * Returns the process exit status: 0 on success, 1 on bad input or a
   * failed run, with one message on @p err (rank 0) naming the problem.
   */
  int
  run_command_line(const std::vector<std::string> &arguments,
                   const MPI_Comm                  mpi_communicator,
                   std::ostream                   &out,
                   std::ostream                   &err);
} // namespace ssc

#endif
