#ifndef ssc_linear_algebra_cell_matrix_product_h
#define ssc_linear_algebra_cell_matrix_product_h

#include <deal.II/lac/full_matrix.h>

namespace ssc
{
  using namespace dealii;

  /// Which factor of a cell matrix product is transposed.
  enum class Transposed
  {
    none,
    left,
    right
  };

  /**
   * result = left right (or left^T right, left right^T) for the small
   * dense matrices of one cell, in plain loops. The cell kernels use this
   * instead of FullMatrix::mmult and its kin because those hand any
   * product of more than 300 multiply-adds to BLAS, and the cell loops run
   * on threads: Debian's default OpenBLAS (libopenblas0-serial) is not
   * safe to call from two threads at once (it gave wrong tangents in the
   * mixed kernels). @p result must have the product's size; it is
   * overwritten.
   */
  void
  multiply(FullMatrix<double>       &result,
           const FullMatrix<double> &left,
           const FullMatrix<double> &right,
           const Transposed          transposed = Transposed::none);
} // namespace ssc

#endif
