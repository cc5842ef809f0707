// The trust-region subproblem min g.p + p.K p / 2, ||p||_M <= radius, by
// truncated_cg() (Steihaug-Toint) on a 1D Laplacian K (n = 40) with a
// Jacobi preconditioner (then M = diag(K), so the M-norm that the CG
// recurrences track can be checked directly), and on K shifted to be
// indefinite:
// - a large radius on the positive definite K gives the CG solution
//   (interior, K p + g = 0 to the tolerance, decrease g.K^-1 g / 2);
// - a small radius stops on the boundary, ||p||_M = radius;
// - on the indefinite K the step follows negative curvature to the
//   boundary and still lowers the model;
// - a constrained entry (projected to zero) stays zero;
// - the predicted decrease equals m(0) - m(p) computed from K.

#include <deal.II/base/index_set.h>

#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <cmath>

#include <ssc/linear_algebra/truncated_cg.h>

#include "tests.h"

using namespace dealii;

namespace
{
  const unsigned int n         = 40;
  const unsigned int fixed_dof = 7; // a "constrained" entry
  using Vector                 = TrilinosWrappers::MPI::Vector;

  /// The 1D Laplacian (Dirichlet ends) minus @p shift on the diagonal, with
  /// the row and column of the fixed dof replaced by a unit diagonal.
  void
  build_matrix(TrilinosWrappers::SparseMatrix &K, const double shift)
  {
    DynamicSparsityPattern pattern(n, n);
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = (i > 0 ? i - 1 : 0); j < std::min(n, i + 2); ++j)
        pattern.add(i, j);
    K.reinit(complete_index_set(n),
             complete_index_set(n),
             pattern,
             MPI_COMM_WORLD);
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = (i > 0 ? i - 1 : 0); j < std::min(n, i + 2); ++j)
        if (i == fixed_dof || j == fixed_dof)
          K.set(i, j, i == j ? 1. : 0.);
        else
          K.set(i, j, i == j ? 2. - shift : -1.);
    K.compress(VectorOperation::insert);
  }

  void
  check(const char                           *name,
        const TrilinosWrappers::SparseMatrix &K,
        const double                          radius,
        const double                          tolerance)
  {
    TrilinosWrappers::PreconditionJacobi jacobi;
    jacobi.initialize(K);
    Vector rhs(complete_index_set(n), MPI_COMM_WORLD), step(rhs), Kp(rhs);
    // -g: a smooth load and a kink, zero on the fixed dof
    for (unsigned int i = 0; i < n; ++i)
      rhs[i] = i == fixed_dof ? 0. : 1. + (i == 20 ? 5. : 0.);
    const auto                   project = [](Vector &v) { v[fixed_dof] = 0.; };
    const ssc::TruncatedCGReport report =
      ssc::truncated_cg(K, jacobi, rhs, radius, tolerance, 200, project, step);
    // the M-norm and the model from K directly
    double M_norm = 0.;
    for (unsigned int i = 0; i < n; ++i)
      M_norm += K.diag_element(i) * step[i] * step[i];
    M_norm = std::sqrt(M_norm);
    K.vmult(Kp, step);
    const double model = -(rhs * step) + 0.5 * (step * Kp);
    Vector       residual(Kp);
    residual -= rhs;
    residual[fixed_dof] = 0.;
    deallog << name << ": " << report.iterations << " CG iterations, "
            << (report.on_boundary ? "on the boundary" : "inside")
            << (report.negative_curvature ? ", negative curvature" : "")
            << std::endl;
    deallog << "  ||p||_M = " << M_norm << " (recurrences " << report.step_norm
            << "), radius " << (radius > 0 ? radius : report.gradient_norm)
            << std::endl;
    deallog << "  predicted decrease " << report.predicted_decrease
            << ", from K " << -model << ", match to 1e-10: "
            << (std::abs(report.predicted_decrease + model) <=
                    1e-10 * std::abs(model) ?
                  "yes" :
                  "no")
            << std::endl;
    deallog << "  ||K p + g|| "
            << (residual.l2_norm() <= tolerance ?
                  std::string("within the tolerance") :
                  "= " + std::to_string(residual.l2_norm()))
            << ", fixed entry " << step[fixed_dof] << std::endl;
  }
} // namespace


int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  TrilinosWrappers::SparseMatrix K;
  build_matrix(K, 0.);
  // positive definite, radius large enough for the Newton step
  check("positive definite, radius 1e6", K, 1e6, 1e-10);
  // positive definite, small radius
  check("positive definite, radius 300", K, 300., 1e-10);
  // positive definite, the preconditioned gradient's norm as radius
  check("positive definite, radius from the gradient", K, 0., 1e-10);
  // the lowest eigenvalues of the Laplacian (about 0.006 and 0.023 on each
  // part) fall below zero
  build_matrix(K, 0.05);
  check("indefinite, radius 20", K, 20., 1e-10);
  check("indefinite, radius 1e4", K, 1e4, 1e-10);
}
