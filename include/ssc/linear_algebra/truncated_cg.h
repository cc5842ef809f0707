#ifndef ssc_linear_algebra_truncated_cg_h
#define ssc_linear_algebra_truncated_cg_h

#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <functional>

namespace ssc
{
  using namespace dealii;

  /// What one trust-region subproblem solve did.
  struct TruncatedCGReport
  {
    unsigned int iterations = 0;
    /// the step stopped on the trust-region boundary
    bool on_boundary = false;
    /// CG met a direction d with d.K d <= 0 (and followed it to the
    /// boundary)
    bool negative_curvature = false;
    /// the preconditioner was not positive along the residual, so the
    /// preconditioned norm is not a norm there; the step is what CG had
    /// reached
    bool preconditioner_indefinite = false;
    /// ||p||_M of the step, M the inverse of the preconditioner
    double step_norm = 0.;
    /// ||g||_{M^-1} = sqrt(g.P g): the preconditioned gradient's M-norm,
    /// for a good preconditioner close to the Newton step's energy norm (a
    /// natural first radius)
    double gradient_norm = 0.;
    /// m(0) - m(p) = -(g.p + p.K p / 2) >= 0
    double predicted_decrease = 0.;
    /// l2 norm of K p + g
    double final_residual = 0.;
  };

  /**
   * The trust-region subproblem min m(p) = g.p + p.K p / 2 subject to
   * ||p||_M <= radius by preconditioned conjugate gradients truncated at
   * the boundary (Steihaug 1983, Toint 1981; Conn, Gould and Toint,
   * Trust-Region Methods, 2000, algorithm 7.5.1): CG from p = 0 until the
   * residual K p + g falls below @p tolerance (interior: an inexact Newton
   * step), an iterate would leave the region, or a search direction has
   * non-positive curvature, which is then followed to the boundary. The
   * M-norm is that of the preconditioner's inverse (preconditioner P
   * approximates K^-1), whose growth along the CG iterates follows from
   * recurrences without applying M. Unlike a CG solve, an indefinite K is
   * no failure: the step lowers the model, and along negative curvature
   * leads off a saddle. @p radius <= 0 takes the preconditioned gradient's
   * M-norm as the radius. @p project zeroes the constrained entries of a
   * vector (homogeneous constraints), applied to each preconditioned
   * residual so that the step never touches them. The right-hand side
   * @p rhs is -g, as assembled for Newton's update.
   */
  TruncatedCGReport
  truncated_cg(
    const TrilinosWrappers::SparseMatrix                       &K,
    const TrilinosWrappers::PreconditionBase                   &P,
    const TrilinosWrappers::MPI::Vector                        &rhs,
    const double                                                radius,
    const double                                                tolerance,
    const unsigned int                                          max_iterations,
    const std::function<void(TrilinosWrappers::MPI::Vector &)> &project,
    TrilinosWrappers::MPI::Vector                              &step);
} // namespace ssc

#endif
