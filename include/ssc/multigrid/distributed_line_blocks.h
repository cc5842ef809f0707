#ifndef ssc_multigrid_distributed_line_blocks_h
#define ssc_multigrid_distributed_line_blocks_h

#include <deal.II/base/point.h>

#include <deal.II/lac/trilinos_vector.h>

#include <Epetra_CrsMatrix.h>
#include <Epetra_Import.h>
#include <Epetra_Map.h>
#include <Epetra_Vector.h>

#include <memory>
#include <vector>

#include <ssc/linear_algebra/line_block_preconditioner.h>

namespace ssc
{
  using namespace dealii;

  /**
   * The exact inverse of a distributed matrix's vertical line blocks, with
   * the lines whole although the partition cuts some of them.
   *
   * Why: p4est partitions the mesh along its own order of the coarse cells,
   * which cuts some columns of cells between two processes. Solving each
   * process's part of such a line alone drops the strong coupling across
   * the thin layers exactly where the line is cut, and the V-cycle's
   * iterations grow fourfold on two processes (17 to 68 on the 39k-DoF
   * test punch). Here each cut line is solved whole by one process, the
   * one holding most of its DoFs: the rows of the other processes' DoFs of
   * its lines are imported once, their values at each application, and the
   * solution is sent back. One process and uncut lines cost nothing extra.
   */
  class DistributedLineBlocks
  {
  public:
    /// Factorises the line blocks of @p matrix. @p lines numbers this
    /// process's DoFs (the matrix's rows, local order) by line, with their
    /// position along it; @p lateral is each line's (x, y), equal on all
    /// processes within @p tolerance. Collective; false on every process
    /// if a line's block is not positive definite on one.
    bool
    initialize(const Epetra_CrsMatrix      &matrix,
               const DoFLines              &lines,
               const std::vector<Point<2>> &lateral,
               const double                 tolerance);

    /// dst = D^{-1} src with D the line-block diagonal. Collective.
    void
    vmult(TrilinosWrappers::MPI::Vector       &dst,
          const TrilinosWrappers::MPI::Vector &src) const;

    /// The same: D is symmetric.
    void
    Tvmult(TrilinosWrappers::MPI::Vector       &dst,
           const TrilinosWrappers::MPI::Vector &src) const;

    /// Number of lines that the partition cuts, over all processes.
    unsigned int
    n_cut_lines() const;

  private:
    LineBlockPreconditioner blocks;
    unsigned int            cut_lines = 0;
    /// This process's DoFs, then the other processes' DoFs of the cut
    /// lines it solves; and the import from the matrix's rows to these.
    std::unique_ptr<Epetra_Map>    extended_map;
    std::unique_ptr<Epetra_Import> import;
    /// Local numbers (extended map) of this process's DoFs on cut lines
    /// that another process solves.
    std::vector<int>                       given_away;
    mutable std::unique_ptr<Epetra_Vector> extended_src, extended_dst;
  };
} // namespace ssc

#endif
