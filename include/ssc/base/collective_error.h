#ifndef ssc_base_collective_error_h
#define ssc_base_collective_error_h

#include <deal.II/base/mpi.h>

#include <functional>
#include <string>

namespace ssc
{
  using namespace dealii;

  /**
   * Runs @p work on every rank of @p communicator and makes its failure
   * collective: if @p work throws on any rank, every rank throws the
   * message of the lowest failing rank (ExcMessage), so that no rank waits
   * in a later collective call for one that gave up. Collective: every
   * rank must call it.
   */
  void
  run_collectively(const std::function<void()> &work,
                   const MPI_Comm               communicator);
} // namespace ssc

#endif
