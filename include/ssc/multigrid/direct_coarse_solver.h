#ifndef ssc_multigrid_direct_coarse_solver_h
#define ssc_multigrid_direct_coarse_solver_h

#include <deal.II/lac/sparse_direct.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <deal.II/multigrid/mg_base.h>

namespace ssc
{
  using namespace dealii;

  /**
   * The exact inverse of a multigrid hierarchy's coarsest matrix (sparse
   * LU, UMFPACK): the coarse mesh of a layered patch has a few thousand
   * DoFs, for which a factorisation is cheaper than iterating (deal.II 9.4
   * has no coarse solver that applies a factor).
   */
  class DirectCoarseSolver : public MGCoarseGridBase<Vector<double>>
  {
  public:
    void
    initialize(const SparseMatrix<double> &matrix)
    {
      factor.initialize(matrix);
    }

    void
    operator()(const unsigned int,
               Vector<double>       &dst,
               const Vector<double> &src) const override
    {
      factor.vmult(dst, src);
    }

  private:
    SparseDirectUMFPACK factor;
  };
} // namespace ssc

#endif
