#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>

#include <Epetra_MultiVector.h>
#include <cholmod.h>

#include <algorithm>
#include <vector>

#include <ssc/linear_algebra/cholesky_preconditioner.h>
#include <ssc/linear_algebra/factor_operator.h>

namespace ssc
{
  /**
   * CHOLMOD's factor of one matrix, as the Epetra operator whose inverse
   * Krylov solvers apply. The matrix is copied into CHOLMOD's compressed
   * column form (its lower triangle); the pattern of the last copy decides
   * whether the symbolic analysis can be reused.
   */
  class CholeskyPreconditioner::Factorization : public FactorOperator
  {
  public:
    explicit Factorization(const Epetra_CrsMatrix &matrix)
      : FactorOperator(matrix.RowMap())
    {
      cholmod_start(&common);
      common.print = 0; // failures are reported through the return values
      // L L^T also where CHOLMOD chooses a simplicial factor (little fill):
      // its default there, L D L^T, would accept an indefinite matrix
      common.final_ll = 1;
    }

    ~Factorization()
    {
      if (factor != nullptr)
        cholmod_free_factor(&factor, &common);
      cholmod_finish(&common);
    }

    bool
    factorize(const Epetra_CrsMatrix &matrix)
    {
      positive_definite = false; // until this factorisation succeeds
      // lower triangle by columns = upper triangle by rows (symmetric)
      UpperTriangle        upper        = upper_triangle(matrix);
      const int            n            = matrix.NumMyRows();
      std::vector<int>    &column_start = upper.row_start, &row = upper.column;
      std::vector<double> &value        = upper.value;
      const bool           same_pattern = factor != nullptr &&
                                column_start == pattern_start &&
                                row == pattern_row;
      if (!same_pattern && factor != nullptr)
        cholmod_free_factor(&factor, &common);

      cholmod_sparse A;
      A.nrow   = n;
      A.ncol   = n;
      A.nzmax  = row.size();
      A.p      = column_start.data();
      A.i      = row.data();
      A.nz     = nullptr;
      A.x      = value.data();
      A.z      = nullptr;
      A.stype  = -1; // lower triangle stored
      A.itype  = CHOLMOD_INT;
      A.xtype  = CHOLMOD_REAL;
      A.dtype  = CHOLMOD_DOUBLE;
      A.sorted = 0;
      A.packed = 1;
      if (!same_pattern)
        {
          factor = cholmod_analyze(&A, &common);
          AssertThrow(factor != nullptr,
                      ExcMessage("CHOLMOD could not analyse the matrix (" +
                                 std::to_string(n) + " rows, status " +
                                 std::to_string(common.status) + ")."));
          pattern_start = std::move(column_start);
          pattern_row   = std::move(row);
        }
      cholmod_factorize(&A, factor, &common);
      AssertThrow(common.status == CHOLMOD_OK ||
                    common.status == CHOLMOD_NOT_POSDEF,
                  ExcMessage("CHOLMOD failed to factorise the matrix "
                             "(status " +
                             std::to_string(common.status) +
                             "; out of memory?)."));
      positive_definite = common.status == CHOLMOD_OK;
      return positive_definite;
    }

    bool
    usable() const
    {
      return factor != nullptr && positive_definite;
    }

    int
    ApplyInverse(const Epetra_MultiVector &X,
                 Epetra_MultiVector       &Y) const override
    {
      for (int v = 0; v < X.NumVectors(); ++v)
        {
          cholmod_dense b;
          b.nrow           = X.MyLength();
          b.ncol           = 1;
          b.nzmax          = b.nrow;
          b.d              = b.nrow;
          b.x              = const_cast<double *>(X[v]);
          b.z              = nullptr;
          b.xtype          = CHOLMOD_REAL;
          b.dtype          = CHOLMOD_DOUBLE;
          cholmod_dense *x = cholmod_solve(CHOLMOD_A, factor, &b, &common);
          if (x == nullptr)
            return -1;
          std::copy_n(static_cast<const double *>(x->x), b.nrow, Y[v]);
          cholmod_free_dense(&x, &common);
        }
      return 0;
    }

    const char *
    Label() const override
    {
      return "ssc CHOLMOD Cholesky factor";
    }

  private:
    mutable cholmod_common common;
    cholmod_factor        *factor            = nullptr;
    bool                   positive_definite = false;
    std::vector<int>       pattern_start, pattern_row;
  };


  void
  CholeskyPreconditioner::require_one_process(const MPI_Comm communicator)
  {
    AssertThrow(Utilities::MPI::n_mpi_processes(communicator) == 1,
                ExcMessage("Elasticity/Linear solver/Preconditioner = "
                           "cholesky factorises the whole matrix on one "
                           "process: run on one MPI rank, or use ldlt (the "
                           "factor distributed over the ranks) or amg."));
  }


  bool
  CholeskyPreconditioner::initialize(
    const TrilinosWrappers::SparseMatrix &matrix)
  {
    require_one_process(matrix.get_mpi_communicator());
    return refactorize(matrix, factorization, preconditioner);
  }


  bool
  CholeskyPreconditioner::factorized() const
  {
    return factorization != nullptr && factorization->usable();
  }


} // namespace ssc
