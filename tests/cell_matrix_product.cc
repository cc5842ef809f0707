// The cell kernels' dense products (ssc::multiply) equal deal.II's
// FullMatrix::mmult, Tmmult and mTmult to round-off for the sizes of a Q2
// cell with a P1 pressure (4 x 81 times 81 x 81, far above the 300
// multiply-adds where deal.II calls BLAS), and give the same result when
// eight products run at once on the cell loops' threads.

#include <deal.II/base/thread_management.h>

#include <cmath>

#include <ssc/linear_algebra/cell_matrix_product.h>

#include "tests.h"

using namespace dealii;

namespace
{
  FullMatrix<double>
  filled(const unsigned int m, const unsigned int n, const double seed)
  {
    FullMatrix<double> matrix(m, n);
    for (unsigned int i = 0; i < m; ++i)
      for (unsigned int j = 0; j < n; ++j)
        matrix(i, j) = std::sin(seed + 1.3 * i + 0.7 * j * j);
    return matrix;
  }

  double
  relative_difference(const FullMatrix<double> &a, const FullMatrix<double> &b)
  {
    FullMatrix<double> difference(a);
    difference.add(-1., b);
    return difference.frobenius_norm() / b.frobenius_norm();
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  const FullMatrix<double> pressure  = filled(4, 4, 0.1),
                           coupling  = filled(4, 81, 0.2),
                           stiffness = filled(81, 81, 0.3);

  // ssc::multiply against deal.II's product of the same kind
  const auto compare = [](const std::string        &label,
                          const FullMatrix<double> &left,
                          const FullMatrix<double> &right,
                          const ssc::Transposed     transposed) {
    const bool left_t  = transposed == ssc::Transposed::left,
               right_t = transposed == ssc::Transposed::right;
    FullMatrix<double> ours(left_t ? left.n() : left.m(),
                            right_t ? right.m() : right.n());
    FullMatrix<double> theirs(ours.m(), ours.n());
    ssc::multiply(ours, left, right, transposed);
    if (left_t)
      left.Tmmult(theirs, right);
    else if (right_t)
      left.mTmult(theirs, right);
    else
      left.mmult(theirs, right);
    deallog << label << ": "
            << (relative_difference(ours, theirs) < 1e-14 ? "equal" : "differ")
            << std::endl;
    return ours;
  };
  const FullMatrix<double> ours =
    compare("A B   against mmult ", pressure, coupling, ssc::Transposed::none);
  const FullMatrix<double> ours_t =
    compare("A^T B against Tmmult", coupling, ours, ssc::Transposed::left);
  compare("A B^T against mTmult", coupling, stiffness, ssc::Transposed::right);

  // eight products at once on threads: each must equal the serial one
  MultithreadInfo::set_thread_limit(2);
  std::vector<FullMatrix<double>> results(8, FullMatrix<double>(81, 81));
  Threads::TaskGroup<void>        tasks;
  for (auto &result : results)
    tasks += Threads::new_task([&result, &coupling, &ours]() {
      for (unsigned int repeat = 0; repeat < 50; ++repeat)
        ssc::multiply(result, coupling, ours, ssc::Transposed::left);
    });
  tasks.join_all();
  bool same = true;
  for (const auto &result : results)
    same = same && relative_difference(result, ours_t) == 0.;
  deallog << "eight products on threads equal the serial one: "
          << (same ? "yes" : "no") << std::endl;
}
