#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

#include <ssc/nonlinear/forcing_term.h>
#include <ssc/nonlinear/line_search.h>
#include <ssc/nonlinear/newton_solver.h>
#include <ssc/nonlinear/trust_region.h>

namespace ssc
{
  /// The state of one solve: residual and tolerance, which globalisation
  /// is active and how far it has come.
  struct NewtonSolver::Iteration
  {
    NewtonReport                 report;
    NonlinearProblem::VectorType start;
    double                       residual = 0, gap = 0, target = 0;
    double                       load_scale = 0;
    /// the residual and the step of the iteration that was just taken
    double trial = 0, step = 1.;
    /// the pseudo-transient shift (0: Newton's method with line search);
    /// the continuation hands back to Newton once it has lowered the
    /// residual tenfold, and resumes with its last shift if Newton fails
    double shift = 0, last_shift = 0, continuation_start = 0;
    /// trust-region steps instead (radius <= 0: not yet known)
    bool         trust_region = false;
    double       radius = 0, first_radius = 0;
    bool         reuse_tangent           = false;
    unsigned int continuation_iterations = 0;
    unsigned int newton_iterations       = 0;
    /// the relative accuracy of the next update (0: the linear solver's own
    /// tolerance)
    bool   inexact = false;
    double forcing = 0;
    /// the prescribed values are still to be reached
    bool closing = false;
  };


  namespace
  {
    /// Prescribed values count as reached within this distance (mm).
    constexpr double gap_tolerance = 1e-12;
  } // namespace


  NewtonSolver::NewtonSolver(NonlinearProblem       &problem,
                             const NewtonParameters &parameters,
                             ConditionalOStream     &pcout,
                             const bool              verbose)
    : problem(problem)
    , parameters(parameters)
    , pcout(pcout)
    , verbose(verbose)
  {}


  bool
  NewtonSolver::continuation_exhausted(const Iteration &it) const
  {
    return it.continuation_iterations >= parameters.continuation_iterations;
  }


  NewtonReport
  NewtonSolver::solve()
  {
    Iteration it;
    it.start    = problem.state();
    it.residual = problem.residual();
    it.gap      = problem.constraint_gap();
    if (!std::isfinite(it.residual))
      {
        it.report.failure = "inverted cells at the start of the increment";
        return it.report;
      }
    it.report.residuals.push_back(it.residual);
    // The tolerance is relative to the scale of the load: the residual at
    // the start of the increment or the applied forces, whichever is
    // larger, so that a cut increment is not asked for more absolute
    // accuracy than the whole load. While prescribed displacements are
    // still to be reached, the residual says nothing about convergence:
    // the tolerance is set once they are met.
    it.load_scale   = std::max(it.residual, problem.applied_load());
    it.target       = it.gap > gap_tolerance ?
                        0. :
                        std::max(parameters.absolute_tolerance,
                           parameters.relative_tolerance * it.load_scale);
    it.trust_region = parameters.globalisation == Globalisation::trust_region;
    it.inexact      = parameters.forcing_term == ForcingTerm::eisenstat_walker;
    it.forcing      = it.inexact ? parameters.max_forcing_term : 0.;
    if (verbose)
      pcout << "    Newton: residual " << std::scientific
            << std::setprecision(3) << it.residual << std::defaultfloat
            << std::endl;
    while (it.gap > gap_tolerance || it.residual > it.target)
      {
        if (it.newton_iterations == parameters.max_iterations)
          {
            it.report.failure = "no convergence in " +
                                std::to_string(parameters.max_iterations) +
                                " iterations";
            return it.report;
          }
        if ((it.shift > 0 || it.trust_region) && continuation_exhausted(it))
          {
            if (verbose)
              {
                // where the iterates went: the change since the start
                auto change = problem.state();
                change -= it.start;
                pcout << "    change of the solution over the increment: "
                      << problem.describe_change(change) << std::endl;
              }
            it.report.failure =
              (it.trust_region ? "the trust-region steps" :
                                 "the pseudo-transient continuation") +
              std::string(" did not converge in ") +
              std::to_string(parameters.continuation_iterations) +
              " iterations";
            return it.report;
          }
        // after a rejected trust-region step only the residual at the
        // restored state is needed: the tangent and its preconditioner are
        // still those of this point
        if (it.reuse_tangent)
          problem.residual();
        else
          problem.tangent();
        // the scale of the load: the right-hand side of the first update
        // (prescribed displacements) or the initial residual (forces)
        if (it.report.iterations == 0)
          it.load_scale = std::max(it.load_scale, problem.rhs_norm());
        if (it.shift > 0)
          problem.shift_tangent(it.shift);
        it.closing            = it.gap > gap_tolerance;
        it.step               = 1.;
        it.trial              = 0.;
        const Outcome outcome = it.trust_region && !it.closing ?
                                  trust_region_iteration(it) :
                                  update_iteration(it);
        if (outcome == Outcome::failed)
          return it.report;
        if (outcome == Outcome::retry)
          continue;

        ++it.report.iterations;
        if (it.inexact)
          it.forcing = eisenstat_walker(it.forcing,
                                        it.trial / it.residual,
                                        parameters.max_forcing_term);
        it.residual = it.trial;
        it.gap      = problem.constraint_gap();
        it.report.residuals.push_back(it.residual);
        if (verbose)
          pcout << "    " << (it.shift > 0 ? "Continuation" : "Newton")
                << " iteration " << it.report.iterations << ": residual "
                << std::scientific << std::setprecision(3) << it.residual
                << std::defaultfloat
                << (it.step < 1. ? ", step " + std::to_string(it.step) :
                                   std::string())
                << (it.shift > 0 ? ", shift " + std::to_string(it.shift) :
                                   std::string())
                << std::endl;
        if (!std::isfinite(it.residual))
          {
            it.report.failure = "inverted cells";
            return it.report;
          }
        if (it.closing && it.gap <= gap_tolerance)
          it.target = std::max(parameters.absolute_tolerance,
                               parameters.relative_tolerance *
                                 std::max(it.residual, it.load_scale));
      }
    it.report.converged = true;
    return it.report;
  }


  NewtonSolver::Outcome
  NewtonSolver::trust_region_iteration(Iteration &it)
  {
    const TrustRegionStep step = trust_region_step(
      problem, it.radius, it.forcing, it.target, !it.reuse_tangent);
    it.reuse_tangent = !step.accepted;
    it.report.linear_iterations += step.update.iterations;
    if (it.first_radius == 0.)
      it.first_radius = it.radius;
    // only a Newton step (inside the region) counts as one
    if (step.update.on_boundary || !step.accepted)
      ++it.continuation_iterations;
    else
      ++it.newton_iterations;
    if (verbose)
      pcout << "    trust region: step " << std::setprecision(3)
            << step.update.step_norm << " ("
            << (step.update.negative_curvature ? "negative curvature, " : "")
            << (step.update.on_boundary ? "on the boundary" : "inside") << ", "
            << step.update.iterations << " CG), energy decrease / predicted "
            << step.ratio << (step.accepted ? "" : ", rejected")
            << "; radius now " << it.radius << std::endl;
    if (!step.accepted)
      {
        if (step.update.preconditioner_indefinite &&
            step.update.step_norm == 0.)
          {
            it.report.failure = "the preconditioner is not positive "
                                "definite (trust-region step)";
            return Outcome::failed;
          }
        if (it.radius < 1e-10 * it.first_radius)
          {
            it.report.failure = "the trust region collapsed";
            return Outcome::failed;
          }
        return Outcome::retry;
      }
    it.trial = step.residual;
    return Outcome::step;
  }


  NewtonSolver::Outcome
  NewtonSolver::update_iteration(Iteration &it)
  {
    try
      {
        // An update CG could not bring to its target is still an inexact
        // Newton step if it has reduced the residual by the acceptable
        // forcing term, or if its linearised residual is already within
        // Newton's tolerance (near the solution CG's own target, a tenth of
        // that, can lie below what it reaches on an ill-conditioned
        // tangent).
        const double            rhs_norm = problem.rhs_norm();
        const LinearSolveReport linear   = problem.solve_update(
          {it.forcing,
             0.1 * it.target,
             std::max(it.inexact ? parameters.acceptable_forcing_term * rhs_norm :
                                 0.,
                      it.target)});
        it.report.linear_iterations += linear.iterations;
        if (!linear.reached_target && verbose)
          pcout << "    (CG stopped at its iteration limit, relative "
                   "residual "
                << std::setprecision(3) << linear.final_residual / rhs_norm
                << ")" << std::endl;
      }
    catch (const ExceptionBase &e)
      {
        std::ostringstream message;
        e.print_info(message);
        it.report.failure =
          "the linear solver failed (" + Utilities::trim(message.str()) + ")";
        it.report.linear_failure_at_start = it.report.iterations == 0;
        return Outcome::failed;
      }
    problem.store_state();
    return it.shift > 0 ? continuation_iteration(it) : newton_iteration(it);
  }


  NewtonSolver::Outcome
  NewtonSolver::continuation_iteration(Iteration &it)
  {
    // Continuation with the shifted tangent K + shift D, which is positive
    // definite for a large enough shift where K is not. On the energy
    // (Levenberg-Marquardt): the line search takes a step along the
    // (descending) update; a whole step halves the shift, a shortened one
    // doubles it. Otherwise pseudo-transient continuation: the whole step,
    // the shift following the residual (switched evolution relaxation).
    // Either way, no descent (or inverted cells) multiplies the shift by
    // ten, and Newton's method takes over again once the residual has
    // dropped tenfold (on the energy also once the shift has become small).
    const bool on_energy = parameters.line_search == LineSearch::energy;
    ++it.continuation_iterations;
    LineSearchResult search{true, 1., 0.};
    if (on_energy)
      search =
        energy_line_search(problem, it.target, parameters.max_line_search);
    else
      {
        problem.set_state_from_stored(1.);
        search.residual = problem.residual();
        search.accepted = std::isfinite(search.residual);
      }
    if (!search.accepted)
      {
        problem.restore_state();
        it.shift *= 10.;
        return Outcome::retry;
      }
    it.step  = search.step;
    it.trial = search.residual;
    it.shift *= on_energy ? (it.step == 1. ? 0.5 : 2.) : it.trial / it.residual;
    it.last_shift = it.shift;
    if (it.trial < 0.1 * it.continuation_start ||
        (on_energy && it.shift < 1e-3 * parameters.continuation_shift))
      it.shift = 0.;
    return Outcome::step;
  }


  NewtonSolver::Outcome
  NewtonSolver::newton_iteration(Iteration &it)
  {
    ++it.newton_iterations;
    // A step that reaches the prescribed displacements is taken whole;
    // otherwise the line search chooses it.
    LineSearchResult search{true, 1., 0.};
    if (it.closing || parameters.line_search == LineSearch::none)
      {
        problem.set_state_from_stored(1.);
        search.residual = problem.residual();
      }
    else if (parameters.line_search == LineSearch::energy)
      search =
        energy_line_search(problem, it.target, parameters.max_line_search);
    else
      search = residual_line_search(problem,
                                    it.residual,
                                    it.target,
                                    parameters.max_line_search);
    it.step  = search.step;
    it.trial = search.residual;
    if (!search.accepted)
      return line_search_failed(it, search.residual);
    return Outcome::step;
  }


  NewtonSolver::Outcome
  NewtonSolver::line_search_failed(Iteration &it, const double trial)
  {
    problem.restore_state();
    if (it.forcing > 0.)
      {
        // an inexact update may be what fails: solve it again, accurately
        it.forcing = 0.;
        return Outcome::retry;
      }
    // a limit or bifurcation point shows as negative curvature
    const double curvature = problem.update_curvature();
    if (!continuation_exhausted(it))
      {
        // past a stability limit Newton's direction need not lower the
        // residual: continue with trust-region steps or with a shifted
        // tangent
        if (parameters.globalisation == Globalisation::hybrid)
          it.trust_region = true;
        else
          {
            it.shift =
              it.last_shift > 0 ? it.last_shift : parameters.continuation_shift;
            it.continuation_start = it.residual;
          }
        if (verbose)
          {
            pcout << "    line search failed (du.K du/du.du = "
                  << std::setprecision(3) << curvature << "): "
                  << (it.trust_region ? "trust-region steps" :
                                        "pseudo-transient continuation")
                  << std::endl;
            if (curvature < 0)
              pcout << "    unstable direction: " << problem.describe_update()
                    << std::endl;
          }
        return Outcome::retry;
      }
    it.report.failure =
      std::isfinite(trial) ?
        (parameters.line_search == LineSearch::energy ?
           "the line search found no decrease of the energy" :
           "the line search found no decrease of the residual") :
        "every step of the line search inverts cells";
    if (curvature < 0)
      {
        std::ostringstream text;
        text << "; the tangent is indefinite along the Newton direction "
                "(du.K du/du.du = "
             << std::setprecision(3) << curvature << ")";
        it.report.failure += text.str();
      }
    return Outcome::failed;
  }
} // namespace ssc
