#include <deal.II/base/timer.h>

#include <deal.II/dofs/dof_tools.h>

#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/trilinos_solver.h>

#include <Epetra_MultiVector.h>
#include <Epetra_Operator.h>
#include <Teuchos_ParameterList.hpp>

#include <iomanip>
#include <map>
#include <sstream>

#include <ssc/mechanics/linear_solver.h>

namespace ssc
{
  namespace
  {
    /**
     * The preconditioner as AztecOO sees it, counting its applications
     * (one per Krylov iteration) and reporting every 100th once the solve
     * has run for a few seconds: AztecOO itself has no iteration hook.
     */
    class MonitoredPreconditioner : public Epetra_Operator
    {
    public:
      MonitoredPreconditioner(Epetra_Operator    &preconditioner,
                              ConditionalOStream *progress,
                              const std::string  &solver)
        : preconditioner(preconditioner)
        , progress(progress)
        , solver(solver)
      {}

      int
      ApplyInverse(const Epetra_MultiVector &x,
                   Epetra_MultiVector       &y) const override
      {
        ++applications;
        if (progress != nullptr && applications % 100 == 0 &&
            timer.wall_time() > 5.)
          *progress << "  " << solver << ": iteration " << applications
                    << " after " << static_cast<int>(timer.wall_time()) << " s"
                    << std::endl;
        return preconditioner.ApplyInverse(x, y);
      }

      int
      Apply(const Epetra_MultiVector &x, Epetra_MultiVector &y) const override
      {
        return preconditioner.Apply(x, y);
      }

      int
      SetUseTranspose(bool use) override
      {
        return preconditioner.SetUseTranspose(use);
      }

      double
      NormInf() const override
      {
        return preconditioner.NormInf();
      }

      const char *
      Label() const override
      {
        return "ssc monitored preconditioner";
      }

      bool
      UseTranspose() const override
      {
        return preconditioner.UseTranspose();
      }

      bool
      HasNormInf() const override
      {
        return preconditioner.HasNormInf();
      }

      const Epetra_Comm &
      Comm() const override
      {
        return preconditioner.Comm();
      }

      const Epetra_Map &
      OperatorDomainMap() const override
      {
        return preconditioner.OperatorDomainMap();
      }

      const Epetra_Map &
      OperatorRangeMap() const override
      {
        return preconditioner.OperatorRangeMap();
      }

    private:
      Epetra_Operator      &preconditioner;
      ConditionalOStream   *progress;
      const std::string     solver;
      Timer                 timer;
      mutable unsigned long applications = 0;
    };
  } // namespace


  LinearSolver::LinearSolver(const LinearSolverParameters &parameters,
                             const DisplacementField      &field,
                             const BoundaryConstraints    &constraints,
                             ConditionalOStream           *progress)
    : parameters(parameters)
    , field(field)
    , constraints(constraints)
    , progress(progress)
    , gmg(field.dof_handler())
  {
    // refused before any work is done, not at the first solve
    if (parameters.preconditioner == DisplacementPreconditioner::cholesky)
      CholeskyPreconditioner::require_one_process(
        field.dof_handler().get_communicator());
    if (parameters.preconditioner == DisplacementPreconditioner::gmg)
      GeometricMultigridPreconditioner::require_uniform_refinements(
        field.dof_handler().get_triangulation());
  }


  LinearSolver::~LinearSolver()
  {
    // The preconditioner references the near-null space: release it first.
    amg.clear();
    near_null_space.reset();
  }


  void
  LinearSolver::setup_preconditioner(
    const TrilinosWrappers::SparseMatrix &matrix,
    const bool                            allow_indefinite)
  {
    if (parameters.preconditioner == DisplacementPreconditioner::amg)
      {
        setup_amg(matrix);
        return;
      }
    if (parameters.preconditioner == DisplacementPreconditioner::gmg)
      {
        if (gmg.initialize(matrix, constraints.homogeneous()))
          return;
        if (progress != nullptr)
          *progress << "  A line block of the tangent is not positive "
                       "definite, or its coarse matrix is singular: AMG "
                       "instead of the V-cycle"
                    << std::endl;
        setup_amg(matrix);
        return;
      }
    // With ldlt one factorisation tells both: the L D L^T factor is
    // positive definite where it has no negative pivot, and is kept as the
    // indefinite factor otherwise. With cholesky a failed Cholesky
    // factorisation is followed by an L D L^T one. A failed factorisation
    // keeps no factor, a successful one drops the other kind: the factor
    // that is left, or else AMG, is the active one.
    const bool distributed =
      parameters.preconditioner == DisplacementPreconditioner::ldlt;
    if (!distributed)
      ldlt.clear();
    const bool positive_definite =
      distributed ? ldlt.initialize(matrix) && ldlt.negative_pivots() == 0 :
                    cholesky.initialize(matrix);
    if (positive_definite)
      {
        ++n_factorizations;
        return;
      }
    if (allow_indefinite && parameters.factor_indefinite &&
        (distributed ? ldlt.factorized() : ldlt.initialize(matrix)))
      {
        report_indefinite_factor();
        return;
      }
    ldlt.clear();
    report_amg_instead();
    setup_amg(matrix);
  }


  void
  LinearSolver::report_indefinite_factor()
  {
    ++n_indefinite_factorizations;
    if (progress != nullptr)
      *progress << "  The tangent is not positive definite ("
                << ldlt.negative_pivots()
                << " negative eigenvalues): its L D L^T factor" << std::endl;
  }


  void
  LinearSolver::report_amg_instead() const
  {
    if (progress != nullptr)
      *progress << "  The tangent is not positive definite: AMG instead of "
                   "its factor"
                << std::endl;
  }


  void
  LinearSolver::matrix_reinitialized()
  {
    gmg.clear();
  }


  std::string
  LinearSolver::preconditioner_name() const
  {
    return to_string(parameters.method) + " + " +
           to_string(parameters.preconditioner);
  }


  const TrilinosWrappers::PreconditionBase &
  LinearSolver::active_preconditioner() const
  {
    if (cholesky.factorized())
      return cholesky;
    if (ldlt.factorized())
      return ldlt;
    if (gmg.initialized())
      return gmg;
    return amg;
  }


  void
  LinearSolver::setup_amg(const TrilinosWrappers::SparseMatrix &matrix)
  {
    TrilinosWrappers::PreconditionAMG::AdditionalData data;
    data.elliptic              = true;
    data.higher_order_elements = field.fe().degree > 1;
    data.smoother_sweeps       = parameters.smoother_sweeps;
    data.aggregation_threshold = parameters.aggregation_threshold;
    // One mask per component: tells ML that there are 3 PDE equations per
    // node; the null space itself is replaced below.
    std::vector<std::vector<bool>> translation_modes;
    DoFTools::extract_constant_modes(field.dof_handler(),
                                     ComponentMask(3, true),
                                     translation_modes);
    data.constant_modes = translation_modes;

    if (!parameters.rigid_body_modes)
      {
        amg.initialize(matrix, data);
        return;
      }

    Teuchos::ParameterList              ml_list;
    std::unique_ptr<Epetra_MultiVector> unused;
    data.set_parameters(ml_list, unused, matrix);

    // Six rigid-body modes evaluated at the support points of the locally
    // owned dofs: three translations and three infinitesimal rotations.
    const Epetra_Map &map = matrix.trilinos_matrix().DomainMap();
    near_null_space       = std::make_unique<Epetra_MultiVector>(map, 6);
    std::map<types::global_dof_index, Point<3>> support_points;
    DoFTools::map_dofs_to_support_points(field.mapping(),
                                         field.dof_handler(),
                                         support_points);
    unsigned int local = 0;
    for (const auto dof : field.locally_owned_dofs())
      {
        const Point<3>    &x = support_points.at(dof);
        const unsigned int c = constraints.component(dof);
        for (unsigned int m = 0; m < 3; ++m)
          (*near_null_space)[m][local] = (c == m ? 1. : 0.);
        // rotations about x, y, z: omega x X
        const double rot[3][3] = {{0., -x[2], x[1]},
                                  {x[2], 0., -x[0]},
                                  {-x[1], x[0], 0.}};
        for (unsigned int m = 0; m < 3; ++m)
          (*near_null_space)[3 + m][local] = rot[m][c];
        ++local;
      }
    // Three equations per support point: ML aggregates whole nodes (the
    // three components of a point are numbered consecutively).
    ml_list.set("PDE equations", 3);
    if (!parameters.smoothed_aggregation)
      ml_list.set("aggregation: damping factor", 0.);
    ml_list.set("null space: type", "pre-computed");
    ml_list.set("null space: dimension", near_null_space->NumVectors());
    ml_list.set("null space: vectors", near_null_space->Values());
    amg.initialize(matrix, ml_list);
  }


  LinearSolveReport
  LinearSolver::solve(const TrilinosWrappers::SparseMatrix &matrix,
                      TrilinosWrappers::MPI::Vector        &x,
                      const TrilinosWrappers::MPI::Vector  &rhs,
                      const AffineConstraints<double> &solution_constraints,
                      const SolveTarget               &target)
  {
    if (parameters.method == LinearSolverMethod::direct)
      {
        SolverControl                  control(1, 0., false, false);
        TrilinosWrappers::SolverDirect direct(
          control,
          TrilinosWrappers::SolverDirect::AdditionalData(false,
                                                         "Amesos_Mumps"));
        solution_constraints.set_zero(x);
        direct.solve(matrix, x, rhs);
        solution_constraints.distribute(x);
        return LinearSolveReport();
      }
    // A factor (or, if asked for, the V-cycle) of an earlier matrix is
    // used for a limited number of iterations; then the current matrix is
    // factorised (its V-cycle built) and the solve continues from where it
    // stopped.
    const bool reuse =
      (cholesky.factorized() || ldlt.factorized() ||
       (parameters.keep_vcycle && gmg.initialized())) &&
      active_preconditioner().trilinos_operator().OperatorDomainMap().SameAs(
        matrix.trilinos_matrix().DomainMap());
    if (!reuse)
      setup_preconditioner(matrix);
    solution_constraints.set_zero(x);
    const double tolerance =
      std::max(std::max(parameters.tolerance, target.relative_tolerance) *
                 rhs.l2_norm(),
               target.absolute_floor);
    LinearSolveReport report;
    SolverControl     control(reuse ?
                            std::min(parameters.refactorization_iterations,
                                     parameters.max_iterations) :
                            parameters.max_iterations,
                          std::max(tolerance, 1e-300),
                          false,
                          false);
    try
      {
        try
          {
            run_krylov(matrix, x, rhs, control, solution_constraints);
          }
        catch (const SolverControl::NoConvergence &)
          {
            if (!reuse)
              throw;
            report.iterations = control.last_step();
            setup_preconditioner(matrix);
            control.set_max_steps(
              parameters.max_iterations -
              std::min(report.iterations, parameters.max_iterations - 1));
            solution_constraints.set_zero(x);
            run_krylov(matrix, x, rhs, control, solution_constraints);
          }
      }
    catch (const SolverControl::NoConvergence &e)
      {
        // the solver's last iterate stays in x
        report.reached_target = false;
        check_unfinished(e, target, control.tolerance(), "CG");
      }
    report.iterations += control.last_step();
    report.final_residual = control.last_value();
    if (report.reached_target)
      check_true_residual(matrix, x, rhs, tolerance, report.iterations);
    solution_constraints.distribute(x);
    return report;
  }


  void
  LinearSolver::run_krylov(
    const TrilinosWrappers::SparseMatrix &matrix,
    TrilinosWrappers::MPI::Vector        &x,
    const TrilinosWrappers::MPI::Vector  &rhs,
    SolverControl                        &control,
    const AffineConstraints<double>      &solution_constraints)
  {
    try
      {
        TrilinosWrappers::SolverCG    cg(control);
        const MonitoredPreconditioner monitored(
          active_preconditioner().trilinos_operator(), progress, "CG");
        cg.solve(matrix.trilinos_matrix(), x, rhs, monitored);
      }
    catch (const SolverControl::NoConvergence &)
      {
        throw;
      }
    catch (const ExceptionBase &)
      {
        // CG breaks down on an indefinite matrix (a finite-strain tangent
        // past a stability limit): GMRES does not need definiteness
        solution_constraints.set_zero(x);
        TrilinosWrappers::SolverGMRES gmres(
          control, TrilinosWrappers::SolverGMRES::AdditionalData(false, 200));
        try
          {
            const MonitoredPreconditioner monitored(
              active_preconditioner().trilinos_operator(), progress, "GMRES");
            gmres.solve(matrix.trilinos_matrix(), x, rhs, monitored);
          }
        catch (const SolverControl::NoConvergence &)
          {
            throw;
          }
        catch (const ExceptionBase &e)
          {
            std::ostringstream info;
            e.print_info(info);
            AssertThrow(false,
                        ExcMessage(
                          "The linear solver broke down (" +
                          Utilities::trim(info.str()) +
                          "): the system is singular or too badly "
                          "conditioned to solve. Check the moduli and "
                          "thicknesses (Layer stack/<layer>/Young's "
                          "modulus, Poisson's ratio, Thickness) and the "
                          "supports (Elasticity/Sides)."));
          }
      }
  }


  void
  LinearSolver::check_true_residual(
    const TrilinosWrappers::SparseMatrix &matrix,
    const TrilinosWrappers::MPI::Vector  &x,
    const TrilinosWrappers::MPI::Vector  &rhs,
    const double                          tolerance,
    const unsigned int                    iterations)
  {
    TrilinosWrappers::MPI::Vector residual(rhs);
    const double true_residual = matrix.residual(residual, x, rhs);
    // the recursion's residual may drift below what round-off lets the
    // true one reach (1e-6 of the right-hand side is always an answer)
    if (true_residual <= std::max(100. * tolerance, 1e-6 * rhs.l2_norm()))
      return;
    std::ostringstream message;
    message << "CG stopped after " << iterations
            << " iterations at the target residual " << std::scientific
            << std::setprecision(2) << tolerance << ", but K x = rhs is "
            << "left with " << true_residual << " (right-hand side "
            << rhs.l2_norm()
            << "): the update is not an answer; lower Elasticity/Linear "
               "solver/Tolerance or choose another Preconditioner.";
    AssertThrow(false, ExcMessage(message.str()));
  }


  void
  LinearSolver::check_unfinished(const SolverControl::NoConvergence &e,
                                 const SolveTarget                  &target,
                                 const double                        tolerance,
                                 const std::string                  &solver)
  {
    if (e.last_residual <= target.acceptable_residual)
      return;
    std::ostringstream message;
    message << solver << " did not converge in " << e.last_step
            << " iterations (residual " << std::scientific
            << std::setprecision(2) << e.last_residual << ", target "
            << tolerance
            << "); raise Elasticity/Linear solver/Max iterations or check "
               "the model.";
    AssertThrow(false, ExcMessage(message.str()));
  }


  TruncatedCGReport
  LinearSolver::solve_within(const TrilinosWrappers::SparseMatrix &matrix,
                             TrilinosWrappers::MPI::Vector        &step,
                             const TrilinosWrappers::MPI::Vector  &rhs,
                             const AffineConstraints<double> &step_constraints,
                             const double                     radius,
                             const SolveTarget               &target,
                             const bool new_preconditioner)
  {
    // truncated CG needs a positive definite preconditioner
    if (new_preconditioner || ldlt.negative_pivots() > 0)
      setup_preconditioner(matrix, false);
    const double tolerance =
      std::max(std::max(parameters.tolerance, target.relative_tolerance) *
                 rhs.l2_norm(),
               target.absolute_floor);
    const TruncatedCGReport report = truncated_cg(
      matrix,
      active_preconditioner(),
      rhs,
      radius,
      tolerance,
      parameters.max_iterations,
      [&](TrilinosWrappers::MPI::Vector &v) { step_constraints.set_zero(v); },
      step);
    step_constraints.distribute(step);
    return report;
  }
} // namespace ssc
