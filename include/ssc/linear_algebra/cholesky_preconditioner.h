#ifndef ssc_linear_algebra_cholesky_preconditioner_h
#define ssc_linear_algebra_cholesky_preconditioner_h

#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>

#include <memory>

namespace ssc
{
  using namespace dealii;

  /**
   * The sparse Cholesky factorisation K = L L^T of a symmetric positive
   * definite matrix (CHOLMOD's supernodal factorisation with a fill-reducing
   * ordering), applied as a preconditioner: exact for the matrix it was
   * computed from, and a good preconditioner for the tangents of the next
   * Newton iterations, which differ little. Its cost does not depend on
   * nu, the layer contrast or the degree, only on the size and fill of the
   * matrix. The symbolic analysis (ordering, elimination tree) is kept as
   * long as the sparsity pattern stays the same.
   *
   * The factorisation needs the whole matrix on one process: one MPI rank.
   */
  class CholeskyPreconditioner : public TrilinosWrappers::PreconditionBase
  {
  public:
    /// Throws, naming the parameter, unless @p communicator has one
    /// process: the factorisation needs the whole matrix on one.
    static void
    require_one_process(const MPI_Comm communicator);

    /// Factorises @p matrix (its lower triangle). Returns false, and keeps
    /// no factor, if the matrix is not positive definite.
    bool
    initialize(const TrilinosWrappers::SparseMatrix &matrix);

    /// Whether a factor is there to apply.
    bool
    factorized() const;

  private:
    class Factorization;
    std::shared_ptr<Factorization> factorization;
  };
} // namespace ssc

#endif
