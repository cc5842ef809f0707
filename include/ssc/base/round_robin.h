#ifndef ssc_base_round_robin_h
#define ssc_base_round_robin_h

#include <deal.II/base/mpi.h>

#include <vector>

namespace ssc
{
  /**
   * Independent work items shared by the ranks of @p communicator: item i
   * is computed by rank i mod n_ranks, which writes its @p width numbers
   * through compute(i, values); every rank gets all items' numbers, item i
   * at [i * width, (i + 1) * width). They are gathered by a sum over the
   * ranks, exact because each number comes from one rank (and a NaN stays
   * a NaN). Collective; @p compute must not call collective operations on
   * @p communicator.
   */
  template <typename Compute>
  std::vector<double>
  compute_round_robin(const unsigned int n_items,
                      const unsigned int width,
                      const MPI_Comm     communicator,
                      const Compute     &compute)
  {
    const unsigned int rank =
      dealii::Utilities::MPI::this_mpi_process(communicator);
    const unsigned int n_ranks =
      dealii::Utilities::MPI::n_mpi_processes(communicator);
    std::vector<double> values(n_items * width, 0.);
    for (unsigned int i = rank; i < n_items; i += n_ranks)
      compute(i, &values[i * width]);
    dealii::Utilities::MPI::sum(values, communicator, values);
    return values;
  }
} // namespace ssc

#endif
