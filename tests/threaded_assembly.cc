// The cell loops (MeshWorker::mesh_loop) run on threads when ssc has cores
// that no MPI rank takes: the main scene assembles on every core of one
// rank. On the coarse forearm indentation at finite strain with lobules,
// septa, ligaments, the rounded edge in contact and the tangents
// factorised, two threads give the answer of one: depths within 1e-9
// relative at every force, with Q1 and the mean dilatation (the main
// scene's elements), and with Q2-P1 on the layers alone (coarse), whose
// cell kernels multiply dense matrices. A data race in a cell kernel or an
// embedded contribution (shared scratch, a cache written during assembly)
// would break that or crash. (The BLAS race that ssc::multiply avoids did
// not show here when tried; identification_small, small-strain Q2-P1 on
// two threads, fails with it.)

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
  const auto run = [](const unsigned int              threads,
                      const std::vector<std::string> &discretisation) {
    dealii::MultithreadInfo::set_thread_limit(threads);
    std::vector<std::string> extra = {"Run/Name=threaded_assembly_" +
                                      std::to_string(threads)};
    extra.insert(extra.end(), discretisation.begin(), discretisation.end());
    return run_indentation("indentation_neo_hookean.prm",
                           {"Punch/Edge contact=true",
                            "Punch/Tied region=flat face",
                            "Elasticity/Linear solver/Preconditioner=cholesky"},
                           extra);
  };
  for (const auto &[label, discretisation] :
       std::vector<std::pair<std::string, std::vector<std::string>>>{
         {"Q1-P0", {}},
         // mixed (indentation_small.prm); the layers alone on a coarse
         // mesh, to the first force, the whole face tied
         {"Q2-P1",
          {"Elasticity/Degree=2",
           "Punch/Forces=0.1",
           "Punch/Tied region=whole face",
           "Microstructure/Lobules=false",
           "Microstructure/Ligaments/Enabled=false",
           "Mesh/Region of interest/Local refinements=0",
           "Mesh/Cell size=6",
           "Mesh/Core half width=9",
           "Layer stack/deep/Cells across=2"}}})
    {
      const auto one = run(1, discretisation);
      const auto two = run(2, discretisation);

      double largest = 0;
      for (unsigned int i = 0; i < one.depths.size(); ++i)
        largest =
          std::max(largest,
                   std::abs(two.depths[i] - one.depths[i]) / one.depths[i]);
      dealii::deallog << std::setprecision(4) << label
                      << ", depths on one thread:";
      for (const double depth : one.depths)
        dealii::deallog << ' ' << depth;
      dealii::deallog << " mm; two threads the same to 1e-9: "
                      << (two.depths.size() == one.depths.size() &&
                              largest < 1e-9 ?
                            "yes" :
                            "no")
                      << std::endl;
    }
}
