#include <ssc/linear_algebra/cell_matrix_product.h>

namespace ssc
{
  void
  multiply(FullMatrix<double>       &result,
           const FullMatrix<double> &left,
           const FullMatrix<double> &right,
           const Transposed          transposed)
  {
    const bool         left_t  = transposed == Transposed::left;
    const bool         right_t = transposed == Transposed::right;
    const unsigned int m       = left_t ? left.n() : left.m();
    const unsigned int k       = left_t ? left.m() : left.n();
    const unsigned int n       = right_t ? right.m() : right.n();
    AssertDimension(k, right_t ? right.n() : right.m());
    AssertDimension(result.m(), m);
    AssertDimension(result.n(), n);
    for (unsigned int i = 0; i < m; ++i)
      for (unsigned int j = 0; j < n; ++j)
        {
          double value = 0;
          for (unsigned int l = 0; l < k; ++l)
            value += (left_t ? left(l, i) : left(i, l)) *
                     (right_t ? right(j, l) : right(l, j));
          result(i, j) = value;
        }
  }
} // namespace ssc
