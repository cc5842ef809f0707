#ifndef ssc_mechanics_linear_solver_h
#define ssc_mechanics_linear_solver_h

#include <deal.II/base/conditional_ostream.h>

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <memory>
#include <string>

#include <ssc/linear_algebra/cholesky_preconditioner.h>
#include <ssc/linear_algebra/ldlt_preconditioner.h>
#include <ssc/linear_algebra/truncated_cg.h>
#include <ssc/mechanics/boundary_constraints.h>
#include <ssc/mechanics/displacement_field.h>
#include <ssc/mechanics/linear_solver_parameters.h>
#include <ssc/mechanics/pressure_system.h>
#include <ssc/multigrid/geometric_multigrid_preconditioner.h>

class Epetra_MultiVector;

namespace ssc
{
  /// What one linear solve did.
  struct LinearSolveReport
  {
    unsigned int iterations     = 0;
    double       final_residual = 0;
    /// false if CG stopped at its iteration limit with a residual that was
    /// still acceptable
    bool reached_target = true;
  };

  /// The accuracy a solve is asked for: the relative tolerance (at least
  /// the linear solver's own), not below an absolute floor (N), and the
  /// residual at which an unfinished solve is still kept (N).
  struct SolveTarget
  {
    double relative_tolerance  = 0.;
    double absolute_floor      = 0.;
    double acceptable_residual = 0.;
  };

  /**
   * CG with Trilinos ML smoothed-aggregation AMG on the displacement
   * system, the AMG fed with the six rigid-body modes (translations and
   * infinitesimal rotations at the dofs' support points) as near-null
   * space, or with a reused sparse Cholesky factor; GMRES where CG breaks down
   * on an indefinite tangent; the Steihaug-Toint truncated CG for trust-region
   * steps with the same preconditioner.
   */
  class LinearSolver
  {
  public:
    /// A solver for the system of @p field with @p constraints; a solve
    /// that runs longer than a few seconds reports its iterations on
    /// @p progress (if given), so that a long run never looks hung.
    LinearSolver(const LinearSolverParameters &parameters,
                 const DisplacementField      &field,
                 const BoundaryConstraints    &constraints,
                 ConditionalOStream           *progress = nullptr);
    ~LinearSolver();

    /// Builds the preconditioner for @p matrix: with Preconditioner =
    /// cholesky its Cholesky factor, with ldlt its distributed L D L^T
    /// factor; if it is not positive definite, its L D L^T factor where
    /// @p allow_indefinite (GMRES then solves) and AMG otherwise; the AMG
    /// hierarchy with Preconditioner = amg; with gmg the V-cycle, or AMG
    /// where a line block is not positive definite.
    void
    setup_preconditioner(const TrilinosWrappers::SparseMatrix &matrix,
                         const bool allow_indefinite = true);

    /// The method and preconditioner as the parameters name them, e.g.
    /// "cg + ldlt" (summary.json).
    std::string
    preconditioner_name() const;

    /// How many factorisations of positive definite tangents were computed
    /// so far.
    unsigned int
    factorizations() const
    {
      return n_factorizations;
    }

    /// How many L D L^T factorisations of tangents that were not positive
    /// definite were computed so far.
    unsigned int
    indefinite_factorizations() const
    {
      return n_indefinite_factorizations;
    }

    /**
     * Solves @p matrix x = @p rhs from the initial guess @p x (its
     * constrained entries zeroed), to @p target, then distributes @p
     * constraints. At the iteration limit an error unless the residual is
     * below the target's acceptable residual. Sets up the preconditioner
     * first; a Cholesky factor of an earlier matrix is reused for up to
     * Refactorization iterations, then replaced by the current matrix's.
     */
    LinearSolveReport
    solve(const TrilinosWrappers::SparseMatrix &matrix,
          TrilinosWrappers::MPI::Vector        &x,
          const TrilinosWrappers::MPI::Vector  &rhs,
          const AffineConstraints<double>      &constraints,
          const SolveTarget                    &target);

    /**
     * Solves K x = @p rhs for the tangent K = K_0 + B^T C^{-1} B of
     * @p system through its saddle point [K_0 B^T; B -C] [x; p] = [rhs; 0]
     * by FGMRES, preconditioned block-triangularly: AMG on K_0 (no bulk
     * modulus in it) and the cells' Schur approximations, until the
     * residual of @p matrix (K) x = @p rhs meets the tolerance. Targets,
     * constraints and errors as solve().
     */
    LinearSolveReport
    solve_saddle_point(const TrilinosWrappers::SparseMatrix &matrix,
                       const PressureSystem                 &system,
                       TrilinosWrappers::MPI::Vector        &x,
                       const TrilinosWrappers::MPI::Vector  &rhs,
                       const AffineConstraints<double>      &constraints,
                       const SolveTarget                    &target);

    /**
     * The trust-region step of truncated_cg() within @p radius in the
     * preconditioner's norm, to @p target's tolerances; the constrained
     * entries stay zero, @p constraints are distributed afterwards. With
     * @p new_preconditioner the AMG is rebuilt for @p matrix first.
     */
    TruncatedCGReport
    solve_within(const TrilinosWrappers::SparseMatrix &matrix,
                 TrilinosWrappers::MPI::Vector        &step,
                 const TrilinosWrappers::MPI::Vector  &rhs,
                 const AffineConstraints<double>      &constraints,
                 const double                          radius,
                 const SolveTarget                    &target,
                 const bool                            new_preconditioner);

    /// The matrix was set up anew (a new sparsity): drops the V-cycle,
    /// whose finest level refers to the matrix it was built for.
    void
    matrix_reinitialized();

  private:
    /// The AMG hierarchy for @p matrix.
    void
    setup_amg(const TrilinosWrappers::SparseMatrix &matrix);

    /// The preconditioner set up last.
    const TrilinosWrappers::PreconditionBase &
    active_preconditioner() const;

    /// Counts an L D L^T factor of an indefinite tangent and says so.
    void
    report_indefinite_factor();

    /// Says that AMG preconditions a tangent that was to be factorised.
    void
    report_amg_instead() const;

    /// CG on @p matrix x = @p rhs from @p x to @p control, GMRES where CG
    /// breaks down (an indefinite tangent); NoConvergence at the limit.
    void
    run_krylov(const TrilinosWrappers::SparseMatrix &matrix,
               TrilinosWrappers::MPI::Vector        &x,
               const TrilinosWrappers::MPI::Vector  &rhs,
               SolverControl                        &control,
               const AffineConstraints<double>      &constraints);

    /// After a solve that met its target: an error unless the true
    /// residual of @p matrix @p x = @p rhs meets it too (to round-off), so
    /// that no stopping test can pass off a wrong answer.
    static void
    check_true_residual(const TrilinosWrappers::SparseMatrix &matrix,
                        const TrilinosWrappers::MPI::Vector  &x,
                        const TrilinosWrappers::MPI::Vector  &rhs,
                        const double                          tolerance,
                        const unsigned int                    iterations);

    /// After a solve stopped by its iteration limit: an error unless its
    /// residual is still acceptable for @p target.
    static void
    check_unfinished(const SolverControl::NoConvergence &e,
                     const SolveTarget                  &target,
                     const double                        tolerance,
                     const std::string                  &solver);

    const LinearSolverParameters     &parameters;
    const DisplacementField          &field;
    const BoundaryConstraints        &constraints;
    ConditionalOStream               *progress;
    TrilinosWrappers::PreconditionAMG amg;
    /// factorised only with Preconditioner = cholesky; while it holds a
    /// factor, that factor is the active preconditioner
    CholeskyPreconditioner cholesky;
    /// every factor with Preconditioner = ldlt; with cholesky, the factor of
    /// a tangent that is not positive definite; active while it holds one
    LdltPreconditioner ldlt;
    /// the V-cycle with Preconditioner = gmg; active while it holds one
    GeometricMultigridPreconditioner    gmg;
    unsigned int                        n_factorizations            = 0;
    unsigned int                        n_indefinite_factorizations = 0;
    std::unique_ptr<Epetra_MultiVector> near_null_space;
  };
} // namespace ssc

#endif
