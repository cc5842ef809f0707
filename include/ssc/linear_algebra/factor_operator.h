#ifndef ssc_linear_algebra_factor_operator_h
#define ssc_linear_algebra_factor_operator_h

#include <deal.II/lac/trilinos_sparse_matrix.h>

#include <Epetra_CrsMatrix.h>
#include <Epetra_Map.h>
#include <Epetra_Operator.h>
#include <Teuchos_RCP.hpp>

#include <memory>
#include <vector>

namespace ssc
{
  using namespace dealii;

  /**
   * The inverse of a symmetric matrix held as a sparse factor, as the
   * Epetra operator that Krylov solvers apply as their preconditioner: only
   * ApplyInverse() exists, the transpose is the operator itself. The
   * factorisations (CHOLMOD's L L^T, MUMPS's L D L^T) derive from it.
   */
  class FactorOperator : public Epetra_Operator
  {
  public:
    explicit FactorOperator(const Epetra_Map &map);

    int
    Apply(const Epetra_MultiVector &, Epetra_MultiVector &) const override;

    int
    SetUseTranspose(bool use) override;

    double
    NormInf() const override;

    bool
    UseTranspose() const override;

    bool
    HasNormInf() const override;

    const Epetra_Comm &
    Comm() const override;

    const Epetra_Map &
    OperatorDomainMap() const override;

    const Epetra_Map &
    OperatorRangeMap() const override;

  private:
    const Epetra_Map map;
  };


  /// The upper triangle of a symmetric matrix on one process, row by row
  /// with global indices: equally its lower triangle column by column.
  struct UpperTriangle
  {
    std::vector<int>    row_start;
    std::vector<int>    column;
    std::vector<double> value;
  };

  UpperTriangle
  upper_triangle(const Epetra_CrsMatrix &matrix);


  /**
   * (Re)factorises @p matrix into @p factorization (a FactorOperator with a
   * constructor from the matrix and a bool factorize(matrix)), made anew
   * where the matrix's map changed, and points @p preconditioner at it if
   * the factorisation succeeded (at nothing otherwise). Collective where
   * the factorisation is distributed.
   */
  template <typename Factorization>
  bool
  refactorize(const TrilinosWrappers::SparseMatrix &matrix,
              std::shared_ptr<Factorization>       &factorization,
              Teuchos::RCP<Epetra_Operator>        &preconditioner)
  {
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
} // namespace ssc

#endif
