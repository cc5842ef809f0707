// The line blocks of the distributed V-cycle's smoother
// (ssc::DistributedLineBlocks) on a layered box with a thin middle layer,
// Q1, the matrix's rows split into contiguous ranges of the DoF numbering,
// which cuts vertical lines between processes wherever the numbering
// does: the distributed inverse equals the serial line-block inverse
// (ssc::LineBlockPreconditioner on the whole matrix) to round-off, so the
// lines are solved whole; on one process no line is cut.

#include <deal.II/base/point.h>

#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>

#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/lac/vector.h>

#include <cmath>
#include <map>
#include <vector>

#include <ssc/linear_algebra/line_block_preconditioner.h>
#include <ssc/multigrid/distributed_line_blocks.h>
#include <ssc/multigrid/vertical_lines.h>

#include "layered_box.h"
#include "tests.h"

using namespace dealii;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  const MPI_Comm     communicator = MPI_COMM_WORLD;
  const unsigned int rank    = Utilities::MPI::this_mpi_process(communicator),
                     n_ranks = Utilities::MPI::n_mpi_processes(communicator);

  // the whole problem on every process
  Triangulation<3> tria;
  make_layered_box(tria, 2);
  DoFHandler<3> dof_handler(tria);
  dof_handler.distribute_dofs(FESystem<3>(FE_Q<3>(1), 3));
  const auto                n = dof_handler.n_dofs();
  SparsityPattern           sparsity;
  SparseMatrix<double>      matrix;
  AffineConstraints<double> none;
  none.close();
  make_layered_matrix(
    dof_handler, numbers::invalid_unsigned_int, none, sparsity, matrix);
  std::vector<Point<2>> lateral;
  const ssc::DoFLines   lines = ssc::vertical_lines(dof_handler,
                                                  numbers::invalid_unsigned_int,
                                                  1e-8,
                                                  &lateral);

  // the serial reference
  ssc::LineBlockPreconditioner serial;
  serial.initialize(matrix, lines);
  Vector<double> x(n), reference(n);
  for (types::global_dof_index i = 0; i < n; ++i)
    x(i) = std::sin(1. + i);
  serial.vmult(reference, x);

  // rows split into contiguous ranges; this process's lines renumbered
  IndexSet owned(n);
  owned.add_range(rank * n / n_ranks, (rank + 1) * n / n_ranks);
  TrilinosWrappers::SparseMatrix distributed;
  distributed.reinit(owned, owned, matrix, communicator);
  ssc::DoFLines                        mine;
  std::vector<Point<2>>                mine_lateral;
  std::map<unsigned int, unsigned int> local_line;
  for (const auto i : owned)
    {
      const auto [entry, added] =
        local_line.emplace(lines.line[i], local_line.size());
      if (added)
        mine_lateral.push_back(lateral[lines.line[i]]);
      mine.line.push_back(entry->second);
      mine.position.push_back(lines.position[i]);
    }
  ssc::DistributedLineBlocks blocks;
  const bool                 factorized =
    blocks.initialize(distributed.trilinos_matrix(), mine, mine_lateral, 1e-8);

  TrilinosWrappers::MPI::Vector src(owned, communicator),
    dst(owned, communicator);
  for (const auto i : owned)
    src(i) = x(i);
  src.compress(VectorOperation::insert);
  blocks.vmult(dst, src);
  double error = 0, norm = 0;
  for (const auto i : owned)
    {
      error += std::pow(dst(i) - reference(i), 2);
      norm += std::pow(reference(i), 2);
    }
  error = std::sqrt(Utilities::MPI::sum(error, communicator) /
                    Utilities::MPI::sum(norm, communicator));
  deallog << n << " DoFs, " << lateral.size() << " lines on " << n_ranks
          << " process(es): factorised " << (factorized ? "yes" : "no")
          << ", lines cut by the partition " << blocks.n_cut_lines()
          << std::endl;
  deallog << "distributed = serial line-block inverse: "
          << (error < 1e-12 ? "yes (relative error < 1e-12)" : "no")
          << std::endl;
}
