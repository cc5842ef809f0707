#ifndef ssc_linear_algebra_ldlt_preconditioner_h
#define ssc_linear_algebra_ldlt_preconditioner_h

#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>

#include <memory>

namespace ssc
{
  using namespace dealii;

  /**
   * The sparse symmetric-indefinite factorisation K = L D L^T (MUMPS,
   * multifrontal, with 1x1 and 2x2 pivots and a fill-reducing ordering) of a
   * symmetric matrix, applied as a preconditioner. It is the factor for the
   * tangents that CholeskyPreconditioner refuses: a finite-strain tangent
   * away from equilibrium (a Newton iterate that overshoots, a stability
   * limit) is symmetric but indefinite, and AMG under GMRES needs
   * thousands of iterations on it. Exact for the matrix it was computed
   * from; the symbolic analysis is kept while the sparsity pattern stays
   * the same. Krylov solvers that need a positive definite preconditioner
   * (CG, the truncated CG of trust-region steps) can use it only where it
   * has no negative pivot (then the matrix is positive definite): GMRES can
   * always.
   *
   * The factorisation is distributed over the processes of the matrix's
   * communicator (MUMPS with distributed input): every process calls
   * initialize() and applies the factor together.
   */
  class LdltPreconditioner : public TrilinosWrappers::PreconditionBase
  {
  public:
    /// Factorises @p matrix (its upper triangle; collective). Returns false,
    /// and keeps no factor, if MUMPS finds the matrix numerically singular.
    bool
    initialize(const TrilinosWrappers::SparseMatrix &matrix);

    /// Whether a factor is there to apply.
    bool
    factorized() const;

    /// The number of negative pivots of the last factor: the count of
    /// negative eigenvalues of the matrix (Sylvester's law of inertia).
    unsigned int
    negative_pivots() const;

    /// Drops the factor (the symbolic analysis is kept).
    void
    clear();

  private:
    class Factorization;
    std::shared_ptr<Factorization> factorization;
  };
} // namespace ssc

#endif
