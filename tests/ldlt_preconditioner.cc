// The L D L^T factor (MUMPS, symmetric indefinite, distributed over the
// ranks): for the shifted 1D Laplacian tridiag(-1, 2 - sigma, -1), whose
// eigenvalues 2 - 2 cos(k pi / (n + 1)) - sigma are known, the factor has
// as many negative pivots as the matrix has negative eigenvalues
// (Sylvester's law of inertia), and applying it solves the system;
// refactorising a matrix of the same pattern (the symbolic analysis
// reused) and of a new pattern gives the new solution. The rows are split
// evenly over the ranks: the .mpirun=2 variant gives the same lines. The
// Cholesky factor (one process: the matrix on rank 0 alone) refuses the
// indefinite matrices.

#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/numbers.h>

#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <cmath>

#include <ssc/linear_algebra/cholesky_preconditioner.h>
#include <ssc/linear_algebra/ldlt_preconditioner.h>

#include "tests.h"

namespace
{
  using namespace dealii;

  /// tridiag(-1, 2 - shift, -1) of size n, with the entries (0, n - 1) and
  /// (n - 1, 0) set to @p corner if it is not zero (a new pattern)
  TrilinosWrappers::SparseMatrix
  shifted_laplacian(const unsigned int n,
                    const double       shift,
                    const double       corner,
                    const MPI_Comm     communicator = MPI_COMM_WORLD)
  {
    DynamicSparsityPattern pattern(n, n);
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = (i > 0 ? i - 1 : 0); j < std::min(n, i + 2); ++j)
        pattern.add(i, j);
    if (corner != 0)
      {
        pattern.add(0, n - 1);
        pattern.add(n - 1, 0);
      }
    const IndexSet rows = Utilities::create_evenly_distributed_partitioning(
      Utilities::MPI::this_mpi_process(communicator),
      Utilities::MPI::n_mpi_processes(communicator),
      n);
    TrilinosWrappers::SparseMatrix matrix;
    matrix.reinit(rows, rows, pattern, communicator);
    for (const auto i : rows)
      {
        matrix.set(i, i, 2. - shift);
        if (i > 0)
          matrix.set(i, i - 1, -1.);
        if (i + 1 < n)
          matrix.set(i, i + 1, -1.);
      }
    if (corner != 0 && rows.is_element(0))
      matrix.set(0, n - 1, corner);
    if (corner != 0 && rows.is_element(n - 1))
      matrix.set(n - 1, 0, corner);
    matrix.compress(VectorOperation::insert);
    return matrix;
  }

  /// |K x - b| / |b| for x = the factor applied to b = (1, 2, ..., n)
  double
  relative_residual(const TrilinosWrappers::SparseMatrix &matrix,
                    const ssc::LdltPreconditioner        &factor)
  {
    TrilinosWrappers::MPI::Vector b(matrix.locally_owned_range_indices(),
                                    MPI_COMM_WORLD);
    for (const auto i : b.locally_owned_elements())
      b[i] = i + 1.;
    b.compress(VectorOperation::insert);
    TrilinosWrappers::MPI::Vector x(b), r(b);
    factor.vmult(x, b);
    matrix.vmult(r, x);
    r -= b;
    return r.l2_norm() / b.l2_norm();
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  const unsigned int      n = 100;
  ssc::LdltPreconditioner factor;
  for (const double shift : {-0.1, 0.5, 1.7})
    {
      const TrilinosWrappers::SparseMatrix matrix =
        shifted_laplacian(n, shift, 0.);
      unsigned int negative = 0;
      for (unsigned int k = 1; k <= n; ++k)
        if (2. - 2. * std::cos(k * numbers::PI / (n + 1)) - shift < 0)
          ++negative;
      bool cholesky_accepts = false;
      if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
        {
          ssc::CholeskyPreconditioner cholesky;
          cholesky_accepts =
            cholesky.initialize(shifted_laplacian(n, shift, 0., MPI_COMM_SELF));
        }
      cholesky_accepts =
        Utilities::MPI::broadcast(MPI_COMM_WORLD, cholesky_accepts, 0);
      const bool factorized = factor.initialize(matrix);
      deallog << "shift " << shift << ": " << negative
              << " negative eigenvalues; Cholesky accepts it: "
              << (cholesky_accepts ? "yes" : "no")
              << "; L D L^T factorised: " << (factorized ? "yes" : "no")
              << ", negative pivots " << factor.negative_pivots()
              << ", solves to 1e-10: "
              << (relative_residual(matrix, factor) < 1e-10 ? "yes" : "no")
              << std::endl;
    }
  const TrilinosWrappers::SparseMatrix periodic =
    shifted_laplacian(n, 0.5, -1.);
  factor.initialize(periodic);
  deallog << "a new pattern (periodic, shift 0.5): solves to 1e-10: "
          << (relative_residual(periodic, factor) < 1e-10 ? "yes" : "no")
          << std::endl;
  factor.clear();
  deallog << "cleared: factorized " << (factor.factorized() ? "yes" : "no")
          << std::endl;
}
