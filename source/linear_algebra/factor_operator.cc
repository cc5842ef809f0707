#include <ssc/linear_algebra/factor_operator.h>

namespace ssc
{
  FactorOperator::FactorOperator(const Epetra_Map &map)
    : map(map)
  {}


  int
  FactorOperator::Apply(const Epetra_MultiVector &, Epetra_MultiVector &) const
  {
    return -1; // only the inverse is available
  }


  int
  FactorOperator::SetUseTranspose(bool use)
  {
    return use ? -1 : 0; // symmetric: the transpose is itself
  }


  double
  FactorOperator::NormInf() const
  {
    return 0;
  }


  bool
  FactorOperator::UseTranspose() const
  {
    return false;
  }


  bool
  FactorOperator::HasNormInf() const
  {
    return false;
  }


  const Epetra_Comm &
  FactorOperator::Comm() const
  {
    return map.Comm();
  }


  const Epetra_Map &
  FactorOperator::OperatorDomainMap() const
  {
    return map;
  }


  const Epetra_Map &
  FactorOperator::OperatorRangeMap() const
  {
    return map;
  }


  UpperTriangle
  upper_triangle(const Epetra_CrsMatrix &matrix)
  {
    const int     n = matrix.NumMyRows();
    UpperTriangle upper;
    upper.row_start.assign(n + 1, 0);
    upper.column.reserve(matrix.NumMyNonzeros() / 2 + n);
    upper.value.reserve(matrix.NumMyNonzeros() / 2 + n);
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
              upper.column.push_back(matrix.GCID(indices[k]));
              upper.value.push_back(values[k]);
            }
        upper.row_start[i + 1] = upper.column.size();
      }
    return upper;
  }
} // namespace ssc
