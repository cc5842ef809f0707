#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>

#include <Epetra_CrsMatrix.h>
#include <Epetra_MultiVector.h>
#include <Epetra_Operator.h>
#include <cholmod.h>

#include <algorithm>
#include <vector>

#include <ssc/mechanics/cholesky_preconditioner.h>

namespace ssc
{
  /**
   * CHOLMOD's factor of one matrix, as the Epetra operator whose inverse
   * Krylov solvers apply. The matrix is copied into CHOLMOD's compressed
   * column form (its lower triangle); the pattern of the last copy decides
   * whether the symbolic analysis can be reused.
   */
  class CholeskyPreconditioner::Factorization : public Epetra_Operator
  {
  public:
    explicit Factorization(const Epetra_CrsMatrix &matrix)
      : map(matrix.RowMap())
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
      const int n       = matrix.NumMyRows();
      // lower triangle by columns = upper triangle by rows (symmetric)
      std::vector<int>    column_start(n + 1, 0), row;
      std::vector<double> value;
      row.reserve(matrix.NumMyNonzeros() / 2 + n);
      value.reserve(matrix.NumMyNonzeros() / 2 + n);
      for (int i = 0; i < n; ++i)
        {
          int     length;
          double *values;
          int    *indices;
          matrix.ExtractMyRowView(i, length, values, indices);
          const int global_row = matrix.GRID(i);
          for (int k = 0; k < length; ++k)
            if (matrix.GCID(indices[k]) >= global_row)
              {
                row.push_back(matrix.GCID(indices[k]));
                value.push_back(values[k]);
              }
          column_start[i + 1] = row.size();
        }
      const bool same_pattern = factor != nullptr &&
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

    int
    Apply(const Epetra_MultiVector &, Epetra_MultiVector &) const override
    {
      return -1; // only the inverse is available
    }

    int
    SetUseTranspose(bool use) override
    {
      return use ? -1 : 0; // symmetric: the transpose is itself
    }

    double
    NormInf() const override
    {
      return 0;
    }

    const char *
    Label() const override
    {
      return "ssc CHOLMOD Cholesky factor";
    }

    bool
    UseTranspose() const override
    {
      return false;
    }

    bool
    HasNormInf() const override
    {
      return false;
    }

    const Epetra_Comm &
    Comm() const override
    {
      return map.Comm();
    }

    const Epetra_Map &
    OperatorDomainMap() const override
    {
      return map;
    }

    const Epetra_Map &
    OperatorRangeMap() const override
    {
      return map;
    }

  private:
    const Epetra_Map       map;
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
                           "process: run on one MPI rank, or use amg."));
  }


  bool
  CholeskyPreconditioner::initialize(
    const TrilinosWrappers::SparseMatrix &matrix)
  {
    require_one_process(matrix.get_mpi_communicator());
    const Epetra_CrsMatrix &crs = matrix.trilinos_matrix();
    if (factorization == nullptr ||
        !factorization->OperatorDomainMap().SameAs(crs.RowMap()))
      factorization = std::make_shared<Factorization>(crs);
    preconditioner.reset();
    if (!factorization->factorize(crs))
      return false;
    preconditioner = Teuchos::rcp(factorization.get(), false);
    return true;
  }


  bool
  CholeskyPreconditioner::factorized() const
  {
    return factorization != nullptr && factorization->usable();
  }


} // namespace ssc
