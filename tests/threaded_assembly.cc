// The cell loops (MeshWorker::mesh_loop) run on threads when ssc has cores
// that no MPI rank takes: the main scene assembles on every core of one
// rank. On the coarse forearm indentation at finite strain with lobules,
// septa, ligaments, the rounded edge in contact and the tangents
// factorised, two threads give the answer of one: depths within 1e-9
// relative at every force. A data race in a cell kernel or an embedded
// contribution (shared scratch, a cache written during assembly) would
// break that or crash.

#include <deal.II/base/multithread_info.h>

#include <cmath>
#include <iomanip>

#include "indentation_run.h"
#include "tests.h"

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  const auto run = [](const unsigned int threads) {
    dealii::MultithreadInfo::set_thread_limit(threads);
    return run_indentation("indentation_neo_hookean.prm",
                           {"Punch/Edge contact=true",
                            "Punch/Tied region=flat face",
                            "Elasticity/Linear solver/Preconditioner=cholesky"},
                           {"Run/Name=threaded_assembly_" +
                            std::to_string(threads)});
  };
  const auto one = run(1);
  const auto two = run(2);

  double largest = 0;
  for (unsigned int i = 0; i < one.depths.size(); ++i)
    largest = std::max(largest,
                       std::abs(two.depths[i] - one.depths[i]) / one.depths[i]);
  dealii::deallog << std::setprecision(4) << "depths on one thread:";
  for (const double depth : one.depths)
    dealii::deallog << ' ' << depth;
  dealii::deallog << " mm; two threads the same to 1e-9: "
                  << (two.depths.size() == one.depths.size() && largest < 1e-9 ?
                        "yes" :
                        "no")
                  << std::endl;
}
