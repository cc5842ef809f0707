#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>

#include <Epetra_MultiVector.h>
#include <dmumps_c.h>

#include <algorithm>
#include <string>
#include <vector>

#include <ssc/linear_algebra/factor_operator.h>
#include <ssc/linear_algebra/ldlt_preconditioner.h>

namespace ssc
{
  namespace
  {
    /// MUMPS' control and information arrays as its manual numbers them.
    MUMPS_INT &
    icntl(DMUMPS_STRUC_C &id, const unsigned int i)
    {
      return id.icntl[i - 1];
    }

    MUMPS_INT
    infog(const DMUMPS_STRUC_C &id, const unsigned int i)
    {
      return id.infog[i - 1];
    }
  } // namespace


  /**
   * One MUMPS instance (symmetric, SYM = 2: L D L^T with pivoting) on one
   * process, as the Epetra operator whose inverse Krylov solvers apply. The
   * matrix is passed as the coordinates of its upper triangle (1-based),
   * which MUMPS reads for as long as the instance lives.
   */
  class LdltPreconditioner::Factorization : public FactorOperator
  {
  public:
    explicit Factorization(const Epetra_CrsMatrix &matrix)
      : FactorOperator(matrix.RowMap())
    {
      id.comm_fortran = static_cast<MUMPS_INT>(MPI_Comm_c2f(MPI_COMM_SELF));
      id.par          = 1; // the host works too
      id.sym          = 2; // general symmetric: indefinite allowed
      id.job          = -1;
      dmumps_c(&id);
      AssertThrow(infog(id, 1) >= 0,
                  ExcMessage("MUMPS could not start (INFOG(1) = " +
                             std::to_string(infog(id, 1)) + ")."));
      icntl(id, 1) = -1; // errors are reported through INFOG(1)
      icntl(id, 2) = -1;
      icntl(id, 3) = -1;
      icntl(id, 4) = 0;
    }

    ~Factorization()
    {
      id.job = -2;
      dmumps_c(&id);
    }

    Factorization(const Factorization &) = delete;
    Factorization &
    operator=(const Factorization &) = delete;

    bool
    factorize(const Epetra_CrsMatrix &matrix)
    {
      usable              = false; // until this factorisation succeeds
      const int     n     = matrix.NumMyRows();
      UpperTriangle upper = upper_triangle(matrix);
      value               = std::move(upper.value);
      id.a                = value.data();
      if (!analysed || upper.row_start != pattern.row_start ||
          upper.column != pattern.column)
        {
          // MUMPS reads the triangle as coordinates, 1-based
          pattern = std::move(upper);
          row.clear();
          column.clear();
          for (int i = 0; i < n; ++i)
            for (int k = pattern.row_start[i]; k < pattern.row_start[i + 1];
                 ++k)
              {
                row.push_back(i + 1);
                column.push_back(pattern.column[k] + 1);
              }
          id.n   = n;
          id.nnz = row.size();
          id.irn = row.data();
          id.jcn = column.data();
          id.job = 1;
          dmumps_c(&id);
          AssertThrow(infog(id, 1) >= 0,
                      ExcMessage("MUMPS could not analyse the matrix (" +
                                 std::to_string(n) + " rows, INFOG(1) = " +
                                 std::to_string(infog(id, 1)) + ")."));
          analysed = true;
        }
      // a working space estimated too small (INFOG(1) = -9) is enlarged
      for (unsigned int attempt = 0;; ++attempt)
        {
          id.job = 2;
          dmumps_c(&id);
          if (infog(id, 1) != -9 || attempt == 3)
            break;
          icntl(id, 14) = 2 * std::max<MUMPS_INT>(icntl(id, 14), 20);
        }
      if (infog(id, 1) == -10) // numerically singular
        return false;
      AssertThrow(infog(id, 1) >= 0,
                  ExcMessage("MUMPS failed to factorise the matrix (INFOG(1) "
                             "= " +
                             std::to_string(infog(id, 1)) +
                             "; out of memory?)."));
      usable = true;
      return true;
    }

    bool
    factorized() const
    {
      return usable;
    }

    void
    clear()
    {
      usable = false;
    }

    unsigned int
    negative_pivots() const
    {
      return usable ? infog(id, 12) : 0;
    }

    int
    ApplyInverse(const Epetra_MultiVector &X,
                 Epetra_MultiVector       &Y) const override
    {
      if (!usable)
        return -1;
      for (int v = 0; v < X.NumVectors(); ++v)
        {
          std::copy_n(X[v], X.MyLength(), Y[v]);
          id.rhs  = Y[v]; // overwritten with the solution
          id.nrhs = 1;
          id.lrhs = X.MyLength();
          id.job  = 3;
          dmumps_c(&id);
          if (infog(id, 1) < 0)
            return -1;
        }
      return 0;
    }

    const char *
    Label() const override
    {
      return "ssc MUMPS L D L^T factor";
    }

  private:
    mutable DMUMPS_STRUC_C id       = {};
    bool                   analysed = false;
    bool                   usable   = false;
    /// the pattern of the analysed matrix, and its coordinates for MUMPS
    UpperTriangle          pattern;
    std::vector<MUMPS_INT> row, column;
    std::vector<double>    value;
  };


  bool
  LdltPreconditioner::initialize(const TrilinosWrappers::SparseMatrix &matrix)
  {
    return refactorize(matrix, factorization, preconditioner);
  }


  bool
  LdltPreconditioner::factorized() const
  {
    return factorization != nullptr && factorization->factorized();
  }


  unsigned int
  LdltPreconditioner::negative_pivots() const
  {
    return factorization != nullptr ? factorization->negative_pivots() : 0;
  }


  void
  LdltPreconditioner::clear()
  {
    preconditioner.reset();
    if (factorization != nullptr)
      factorization->clear();
  }
} // namespace ssc
