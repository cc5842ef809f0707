#ifndef ssc_linear_algebra_line_block_preconditioner_h
#define ssc_linear_algebra_line_block_preconditioner_h

#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/lac/vector.h>

#include <Epetra_CrsMatrix.h>

#include <vector>

namespace ssc
{
  using namespace dealii;

  /**
   * DoFs grouped into lines: the number of each DoF's line and its
   * position along it (which orders the DoFs of a line, so that each
   * line's block of the matrix is banded). multigrid/vertical_lines.h
   * makes them from a mesh.
   */
  struct DoFLines
  {
    std::vector<unsigned int> line;
    std::vector<double>       position;
  };


  /**
   * The exact inverse of a symmetric positive definite matrix's line-block
   * diagonal: the couplings between DoFs of the same line are kept, all
   * other couplings are dropped. Each line's block, ordered by position, is
   * banded; it is factorised by LAPACK's banded Cholesky (dpbtrf), so the
   * factor costs (bandwidth + 1) numbers per DoF and one application about
   * as much as a product with the matrix.
   *
   * Why: in the thin layers of the skin/subcutaneous stack the cells are
   * flat (lateral size 10-20 times their thickness), so the stiffness
   * couples a node far more strongly to its neighbours across the layer
   * than along it. A point smoother (Jacobi, Chebyshev on Jacobi) cannot
   * damp error that is smooth across a flat cell and rough along it, and a
   * multigrid V-cycle with it needs ever more iterations. Solving every
   * line across the layers at once is the classical cure for such
   * anisotropy with full coarsening; inside Chebyshev smoothing it keeps
   * the V-cycle at 6-30 CG iterations on the layered punch
   * (benchmarks/multigrid_layered).
   */
  class LineBlockPreconditioner
  {
  public:
    /// Keeps and factorises the couplings of @p matrix within each line.
    /// Returns false, keeping no factor, if a line's block is not positive
    /// definite (an indefinite matrix).
    bool
    initialize(const SparseMatrix<double> &matrix, const DoFLines &lines);

    /// The same for this process's rows of a distributed matrix, and
    /// @p more_rows (other processes' rows, imported): @p lines numbers the
    /// matrix's rows in local order (as vertical_lines() does), then those
    /// of @p more_rows. Couplings to DoFs of neither are dropped.
    bool
    initialize(const Epetra_CrsMatrix &matrix,
               const DoFLines         &lines,
               const Epetra_CrsMatrix *more_rows = nullptr);

    /// dst = D^{-1} src with D the line-block diagonal.
    void
    vmult(Vector<double> &dst, const Vector<double> &src) const;

    /// The same on this process's elements of distributed vectors.
    void
    vmult(TrilinosWrappers::MPI::Vector       &dst,
          const TrilinosWrappers::MPI::Vector &src) const;

    /// The same on contiguous arrays of m() elements.
    void
    vmult(double *dst, const double *src) const;

    /// The same: D is symmetric.
    void
    Tvmult(Vector<double> &dst, const Vector<double> &src) const;

    /// The same: D is symmetric.
    void
    Tvmult(TrilinosWrappers::MPI::Vector       &dst,
           const TrilinosWrappers::MPI::Vector &src) const;

    types::global_dof_index
    m() const;

    types::global_dof_index
    n() const;

    /// Number of lines.
    unsigned int
    n_lines() const;

    /// The largest bandwidth of a line's block.
    unsigned int
    max_bandwidth() const;

  private:
    /// One line: its DoFs in order and its banded Cholesky factor
    /// (LAPACK's lower band storage, bandwidth + 1 rows).
    struct Line
    {
      std::vector<types::global_dof_index> dofs;
      int                                  bandwidth = 0;
      std::vector<double>                  band;
    };

    /// Sorts the DoFs along their lines and factorises the blocks;
    /// @p for_each_in_row(row, visit) calls visit(column, value) for each
    /// entry of a row (local numbers).
    template <typename RowVisitor>
    bool
    factorize(const types::global_dof_index n_rows,
              const DoFLines               &dof_lines,
              const RowVisitor             &for_each_in_row);

    std::vector<Line>       lines;
    types::global_dof_index size = 0;
    /// Room for one line's values during vmult.
    mutable std::vector<double> buffer;
  };
} // namespace ssc

#endif
