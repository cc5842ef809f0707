#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>

#include <Epetra_Import.h>
#include <Epetra_Map.h>
#include <Epetra_MpiComm.h>
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
   * One MUMPS instance (symmetric, SYM = 2: L D L^T with pivoting) on all
   * processes of the matrix's communicator, as the Epetra operator whose
   * inverse Krylov solvers apply. Each process hands MUMPS the coordinates
   * of the upper triangle of its own rows (1-based global indices,
   * distributed assembled input), which MUMPS reads for as long as the
   * instance lives; the right-hand side is gathered on the first process
   * and the solution scattered back (MUMPS's centralised solve).
   */
  class LdltPreconditioner::Factorization : public FactorOperator
  {
  public:
    explicit Factorization(const Epetra_CrsMatrix &matrix)
      : FactorOperator(matrix.RowMap())
      , communicator(dynamic_cast<const Epetra_MpiComm &>(matrix.Comm()).Comm())
      , gathered_map(matrix.NumGlobalRows(),
                     Utilities::MPI::this_mpi_process(communicator) == 0 ?
                       matrix.NumGlobalRows() :
                       0,
                     0,
                     matrix.Comm())
      , gather(gathered_map, matrix.RowMap())
      , gathered(gathered_map, 1)
    {
      AssertThrow(matrix.RowMap().LinearMap(),
                  ExcMessage("The L D L^T factor needs the rows numbered "
                             "consecutively from 0 over the processes."));
      id.comm_fortran = static_cast<MUMPS_INT>(MPI_Comm_c2f(communicator));
      id.par          = 1; // the host works too
      id.sym          = 2; // general symmetric: indefinite allowed
      id.job          = -1;
      dmumps_c(&id);
      AssertThrow(infog(id, 1) >= 0,
                  ExcMessage("MUMPS could not start (INFOG(1) = " +
                             std::to_string(infog(id, 1)) + ")."));
      icntl(id, 1)  = -1; // errors are reported through INFOG(1)
      icntl(id, 2)  = -1;
      icntl(id, 3)  = -1;
      icntl(id, 4)  = 0;
      icntl(id, 18) = 3; // each process gives its own entries
      // the last front factorised on one process, not by ScaLAPACK: its
      // negative pivots are then counted too (the inertia, INFOG(12))
      icntl(id, 13) = 1;
    }

    ~Factorization()
    {
      id.job = -2;
      dmumps_c(&id);
    }

    Factorization(const Factorization &) = delete;
    Factorization &
    operator=(const Factorization &) = delete;

    /// Collective. False, and no factor, where MUMPS finds the matrix
    /// numerically singular.
    bool
    factorize(const Epetra_CrsMatrix &matrix)
    {
      usable                  = false; // until this factorisation succeeds
      UpperTriangle upper     = upper_triangle(matrix);
      value                   = std::move(upper.value);
      id.a_loc                = value.data();
      const bool same_pattern = analysed &&
                                upper.row_start == pattern.row_start &&
                                upper.column == pattern.column;
      if (Utilities::MPI::min(same_pattern ? 1u : 0u, communicator) == 0u)
        {
          // MUMPS reads the triangle as coordinates, 1-based and global
          pattern = std::move(upper);
          row.clear();
          column.clear();
          for (int i = 0; i < matrix.NumMyRows(); ++i)
            for (int k = pattern.row_start[i]; k < pattern.row_start[i + 1];
                 ++k)
              {
                row.push_back(matrix.GRID(i) + 1);
                column.push_back(pattern.column[k] + 1);
              }
          id.n       = matrix.NumGlobalRows();
          id.nnz_loc = row.size();
          id.irn_loc = row.data();
          id.jcn_loc = column.data();
          id.job     = 1;
          dmumps_c(&id);
          AssertThrow(infog(id, 1) >= 0,
                      ExcMessage("MUMPS could not analyse the matrix (" +
                                 std::to_string(id.n) + " rows, INFOG(1) = " +
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

    /// Collective: the solve with the factor, one vector after the other.
    int
    ApplyInverse(const Epetra_MultiVector &X,
                 Epetra_MultiVector       &Y) const override
    {
      if (!usable)
        return -1;
      for (int v = 0; v < X.NumVectors(); ++v)
        {
          const Epetra_MultiVector x(View, X, v, 1);
          Epetra_MultiVector       y(View, Y, v, 1);
          gathered.Import(x, gather, Insert);
          id.rhs  = gathered[0]; // overwritten with the solution
          id.nrhs = 1;
          id.lrhs = std::max(gathered.MyLength(), 1);
          id.job  = 3;
          dmumps_c(&id);
          if (infog(id, 1) < 0)
            return -1;
          y.Export(gathered, gather, Insert);
        }
      return 0;
    }

    const char *
    Label() const override
    {
      return "ssc MUMPS L D L^T factor";
    }

  private:
    const MPI_Comm communicator;
    /// all rows on the first process, where MUMPS takes the right-hand
    /// side and returns the solution, and the import that gathers them
    const Epetra_Map           gathered_map;
    const Epetra_Import        gather;
    mutable Epetra_MultiVector gathered;
    mutable DMUMPS_STRUC_C     id       = {};
    bool                       analysed = false;
    bool                       usable   = false;
    /// this process's part of the analysed pattern, and its coordinates
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
