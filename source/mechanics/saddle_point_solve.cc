// LinearSolver's displacement-pressure (block) solve: FGMRES on the saddle
// point with a block-triangular preconditioner, apart from the Krylov and
// direct solves of linear_solver.cc.

#include <deal.II/base/timer.h>

#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/solver_gmres.h>
#include <deal.II/lac/trilinos_parallel_block_vector.h>

#include <iomanip>
#include <sstream>

#include <ssc/mechanics/linear_solver.h>

namespace ssc
{
  namespace
  {
    /// The saddle point [K_0 B^T; B -C] of a PressureSystem.
    class SaddlePointOperator
    {
    public:
      explicit SaddlePointOperator(const PressureSystem &system)
        : system(system)
      {}

      void
      vmult(TrilinosWrappers::MPI::BlockVector       &dst,
            const TrilinosWrappers::MPI::BlockVector &src) const
      {
        system.reduced_matrix().vmult(dst.block(0), src.block(0));
        system.coupling_matrix().Tvmult_add(dst.block(0), src.block(1));
        system.coupling_matrix().vmult(dst.block(1), src.block(0));
        scratch.reinit(src.block(1), true);
        system.apply_pressure_block(scratch, src.block(1));
        dst.block(1) -= scratch;
      }

    private:
      const PressureSystem                 &system;
      mutable TrilinosWrappers::MPI::Vector scratch;
    };


    /**
     * The block upper-triangular preconditioner [A B^T; 0 -S]^{-1} of the
     * saddle point: S^{-1} from the cells' Schur approximations, A^{-1}
     * one AMG cycle on K_0 (or its Cholesky factor: exact). With exact A and S,
     * GMRES would converge in two iterations.
     */
    class BlockTriangularPreconditioner
    {
    public:
      BlockTriangularPreconditioner(
        const PressureSystem                     &system,
        const TrilinosWrappers::PreconditionBase &displacement)
        : system(system)
        , displacement(displacement)
      {}

      void
      vmult(TrilinosWrappers::MPI::BlockVector       &dst,
            const TrilinosWrappers::MPI::BlockVector &src) const
      {
        system.apply_schur_inverse(dst.block(1), src.block(1));
        dst.block(1) *= -1.;
        scratch.reinit(src.block(0), true);
        system.coupling_matrix().Tvmult(scratch, dst.block(1));
        scratch.sadd(-1., 1., src.block(0));
        displacement.vmult(dst.block(0), scratch);
      }

    private:
      const PressureSystem                     &system;
      const TrilinosWrappers::PreconditionBase &displacement;
      mutable TrilinosWrappers::MPI::Vector     scratch;
    };
  } // namespace


  LinearSolveReport
  LinearSolver::solve_saddle_point(
    const TrilinosWrappers::SparseMatrix &matrix,
    const PressureSystem                 &system,
    TrilinosWrappers::MPI::Vector        &x,
    const TrilinosWrappers::MPI::Vector  &rhs,
    const AffineConstraints<double>      &solution_constraints,
    const SolveTarget                    &target)
  {
    setup_preconditioner(system.reduced_matrix());
    const MPI_Comm communicator = rhs.get_mpi_communicator();
    TrilinosWrappers::MPI::BlockVector solution, right_hand_side;
    const std::vector<IndexSet>        partitioning = {
             rhs.locally_owned_elements(), system.locally_owned_pressure()};
    solution.reinit(partitioning, communicator);
    right_hand_side.reinit(partitioning, communicator);
    right_hand_side.block(0) = rhs;
    const double tolerance =
      std::max(std::max(parameters.tolerance, target.relative_tolerance) *
                 rhs.l2_norm(),
               target.absolute_floor);
    // The saddle point's residual weighs the pressure equations (volumes)
    // differently from the forces: a small one can leave the displacement
    // of a nearly incompressible layer inexact. So the residual of K x =
    // rhs itself is checked, and the saddle point solved further from
    // where it stopped until that meets the tolerance.
    LinearSolveReport             report;
    TrilinosWrappers::MPI::Vector residual(rhs);
    double                        block_tolerance = tolerance;
    Timer                         timer;
    for (unsigned int round = 0;; ++round)
      {
        SolverControl control(parameters.max_iterations - report.iterations,
                              std::max(block_tolerance, 1e-300),
                              false,
                              false);
        SolverFGMRES<TrilinosWrappers::MPI::BlockVector> fgmres(
          control,
          SolverFGMRES<TrilinosWrappers::MPI::BlockVector>::AdditionalData(
            100));
        const unsigned int done = report.iterations;
        fgmres.connect([&](const unsigned int step,
                           const double,
                           const TrilinosWrappers::MPI::BlockVector &) {
          if (progress != nullptr && step > 0 && (done + step) % 100 == 0 &&
              timer.wall_time() > 5.)
            *progress << "  FGMRES: iteration " << done + step << " after "
                      << static_cast<int>(timer.wall_time()) << " s"
                      << std::endl;
          return SolverControl::success;
        });
        bool unfinished = false;
        try
          {
            fgmres.solve(
              SaddlePointOperator(system),
              solution,
              right_hand_side,
              BlockTriangularPreconditioner(system, active_preconditioner()));
          }
        catch (const SolverControl::NoConvergence &e)
          {
            report.reached_target = false;
            unfinished            = true;
            check_unfinished(e, target, control.tolerance(), "FGMRES");
          }
        report.iterations += control.last_step();
        // rhs - K x on the unconstrained rows
        x = solution.block(0);
        solution_constraints.set_zero(x);
        matrix.vmult(residual, x);
        residual.sadd(-1., 1., rhs);
        solution_constraints.set_zero(residual);
        report.final_residual = residual.l2_norm();
        if (unfinished || report.final_residual <= tolerance)
          break;
        if (round == 4)
          {
            // five rounds without meeting the tolerance on K x = rhs
            report.reached_target = false;
            AssertThrow(report.final_residual <= target.acceptable_residual,
                        ExcMessage(
                          "FGMRES on the displacement-pressure system did "
                          "not reduce the residual of the displacement "
                          "equations to the tolerance in five restarts; use "
                          "Elasticity/Linear solver/Method = cg."));
            break;
          }
        block_tolerance *= 0.1 * tolerance / report.final_residual;
      }
    x = solution.block(0);
    solution_constraints.distribute(x);
    return report;
  }
} // namespace ssc
