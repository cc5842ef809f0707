#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <ssc/mechanics/newton_solver.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>

namespace ssc
{
  double
  NewtonSolver::eisenstat_walker(const double previous_forcing,
                                 const double residual_ratio) const
  {
    // Eisenstat and Walker (SIAM J. Sci. Comput. 17, 1996), choice 2 with
    // gamma = 0.9 and alpha = 2, and their safeguard against a forcing term
    // that falls faster than the convergence justifies
    const double gamma     = 0.9;
    double       forcing   = gamma * residual_ratio * residual_ratio;
    const double safeguard = gamma * previous_forcing * previous_forcing;
    if (safeguard > 0.1)
      forcing = std::max(forcing, safeguard);
    return std::min(forcing, parameters.max_forcing_term);
  }


  NewtonSolver::LineSearchResult
  NewtonSolver::residual_line_search(
    const double                                                   residual,
    const double                                                   target,
    const std::vector<std::pair<types::global_dof_index, double>> &nodal_forces)
  {
    // backtracking until the residual norm decreases (Armijo)
    double step = 1., trial = 0.;
    for (unsigned int k = 0; k < parameters.max_line_search; ++k, step *= 0.5)
      {
        elasticity.set_solution_from_stored(step);
        trial = elasticity.assemble_newton_system(false, nodal_forces);
        if (trial <= (1. - 1e-4 * step) * residual || trial <= target)
          return {true, step, trial};
      }
    return {false, 2. * step, trial};
  }


  NewtonSolver::LineSearchResult
  NewtonSolver::energy_line_search(
    const double                                                   target,
    const std::vector<std::pair<types::global_dof_index, double>> &nodal_forces)
  {
    // The energy along the update, phi(s) = Pi(u + s du), has the slope
    // phi'(s) = r(u + s du).du; Newton's direction descends where
    // phi'(0) = -du.K du < 0. Look for a step where the slope has shrunk
    // to half of phi'(0) in magnitude (near the minimum along the line):
    // the whole step if the energy still falls there, else regula falsi
    // in the bracket, backing off from inverted cells.
    const double slope_0 = elasticity.residual_along_update();
    if (!(slope_0 < 0.))
      return {false, 1., 0.};
    double low = 0., slope_low = slope_0, high = 1., slope_high = 0.;
    bool   bracketed = false; // a step with phi' > 0 is known
    double step = 1., trial = 0.;
    for (unsigned int k = 0; k < parameters.max_line_search; ++k)
      {
        elasticity.set_solution_from_stored(step);
        trial = elasticity.assemble_newton_system(false, nodal_forces);
        if (!std::isfinite(trial))
          {
            high      = step;
            bracketed = false;
            step      = 0.5 * (low + high);
            continue;
          }
        const double slope = elasticity.residual_along_update();
        if (trial <= target || std::abs(slope) <= 0.5 * std::abs(slope_0) ||
            (slope < 0. && step == 1.))
          return {true, step, trial};
        if (slope < 0.)
          {
            low       = step;
            slope_low = slope;
          }
        else
          {
            high       = step;
            slope_high = slope;
            bracketed  = true;
          }
        // regula falsi inside the bracket, kept off its ends; halving
        // towards inverted cells
        const double width = high - low;
        if (bracketed)
          {
            const double secant =
              low - slope_low * width / (slope_high - slope_low);
            step = std::clamp(secant, low + 0.1 * width, high - 0.1 * width);
          }
        else
          step = 0.5 * (low + high);
      }
    if (low == 0.)
      return {false, step, trial};
    // the last step where the energy was still falling
    elasticity.set_solution_from_stored(low);
    return {true, low, elasticity.assemble_newton_system(false, nodal_forces)};
  }


  NewtonSolver::TrustRegionStep
  NewtonSolver::trust_region_step(
    double                                                        &radius,
    const double                                                   forcing,
    const double                                                   target,
    const bool                                                     new_tangent,
    const std::vector<std::pair<types::global_dof_index, double>> &nodal_forces)
  {
    TrustRegionStep result{false, 0., 0., {}};
    result.update = elasticity.solve_trust_region_update(radius,
                                                         forcing,
                                                         0.1 * target,
                                                         new_tangent);
    if (radius <= 0.)
      radius = result.update.gradient_norm;
    if (result.update.step_norm == 0.)
      return result;
    // Pi(u + p) - Pi(u) = integral of r(u + s p).p over s in [0, 1]
    elasticity.store_solution();
    const double slope_0 = elasticity.residual_along_update();
    elasticity.set_solution_from_stored(0.5);
    const double middle =
      elasticity.assemble_newton_system(false, nodal_forces);
    const double slope_half = elasticity.residual_along_update();
    elasticity.set_solution_from_stored(1.);
    result.residual = elasticity.assemble_newton_system(false, nodal_forces);
    const double slope_1  = elasticity.residual_along_update();
    const double decrease = -(slope_0 + 4. * slope_half + slope_1) / 6.;
    // a step the model does not predict to descend (possible only with an
    // indefinite preconditioner) counts as a poor one
    result.ratio = std::isfinite(middle) && std::isfinite(result.residual) &&
                       result.update.predicted_decrease > 0. ?
                     decrease / result.update.predicted_decrease :
                     -std::numeric_limits<double>::infinity();
    if (result.ratio < 0.25)
      radius = 0.25 * std::min(radius, result.update.step_norm);
    else if (result.ratio > 0.75 && result.update.on_boundary)
      radius *= 2.;
    result.accepted = result.ratio > 0.05 ||
                      (std::isfinite(middle) && result.residual <= target);
    if (!result.accepted)
      elasticity.restore_solution();
    return result;
  }


  NewtonSolver::NewtonSolver(VolumeElasticity       &elasticity,
                             const NewtonParameters &parameters,
                             ConditionalOStream     &pcout,
                             const bool              verbose)
    : elasticity(elasticity)
    , parameters(parameters)
    , pcout(pcout)
    , verbose(verbose)
  {}


  NewtonReport
  NewtonSolver::solve(
    const std::vector<std::pair<types::global_dof_index, double>> &nodal_forces)
  {
    NewtonReport report;
    const auto   start = elasticity.get_solution();
    double residual    = elasticity.assemble_newton_system(false, nodal_forces);
    double gap         = elasticity.dirichlet_gap();
    if (!std::isfinite(residual))
      {
        report.failure = "inverted cells at the start of the increment";
        return report;
      }
    report.residuals.push_back(residual);
    // The tolerance is relative to the scale of the load: the residual at
    // the start of the increment or the applied forces, whichever is
    // larger, so that a cut increment is not asked for more absolute
    // accuracy than the whole load. While prescribed displacements are
    // still to be reached, the residual says nothing about convergence:
    // the tolerance is set once they are met.
    double applied = 0.;
    for (const auto &force : nodal_forces)
      applied += force.second * force.second;
    const double gap_tolerance = 1e-12;
    double       load_scale    = std::max(residual, std::sqrt(applied));
    double       target        = gap > gap_tolerance ?
                                   0. :
                                   std::max(parameters.absolute_tolerance,
                               parameters.relative_tolerance * load_scale);
    if (verbose)
      pcout << "    Newton: residual " << std::scientific
            << std::setprecision(3) << residual << std::defaultfloat
            << std::endl;
    // the pseudo-transient shift: 0 is Newton's method with line search;
    // the continuation hands back to Newton once it has lowered the
    // residual tenfold, and resumes with its last shift if Newton fails
    double shift = 0., last_shift = 0., continuation_start = 0.;
    // trust-region steps instead (radius <= 0: not yet known)
    bool trust_region = parameters.globalisation == Globalisation::trust_region;
    double       radius = 0., first_radius = 0.;
    bool         reuse_tangent           = false;
    unsigned int continuation_iterations = 0;
    unsigned int newton_iterations       = 0;
    // the forcing term: the relative accuracy of the next update (0: the
    // linear solver's own tolerance)
    const bool inexact =
      parameters.forcing_term == ForcingTerm::eisenstat_walker;
    double     forcing = inexact ? parameters.max_forcing_term : 0.;
    const auto continuation_exhausted = [&]() {
      return continuation_iterations >= parameters.continuation_iterations;
    };
    while (gap > gap_tolerance || residual > target)
      {
        if (newton_iterations == parameters.max_iterations)
          {
            report.failure = "no convergence in " +
                             std::to_string(parameters.max_iterations) +
                             " iterations";
            return report;
          }
        if ((shift > 0 || trust_region) && continuation_exhausted())
          {
            if (verbose)
              {
                // where the iterates went: the change since the start
                auto change = elasticity.get_solution();
                change -= start;
                pcout << "    change of the solution over the increment: "
                      << elasticity.describe_displacement(change) << std::endl;
              }
            report.failure =
              (trust_region ? "the trust-region steps" :
                              "the pseudo-transient continuation") +
              std::string(" did not converge in ") +
              std::to_string(parameters.continuation_iterations) +
              " iterations";
            return report;
          }
        // after a rejected trust-region step only the residual at the
        // restored solution is needed: the tangent and its preconditioner
        // are still those of this point
        elasticity.assemble_newton_system(!reuse_tangent, nodal_forces);
        // the scale of the load: the right-hand side of the first update
        // (prescribed displacements) or the initial residual (forces)
        if (report.iterations == 0)
          load_scale =
            std::max(load_scale, elasticity.get_system_rhs().l2_norm());
        if (shift > 0)
          elasticity.shift_tangent(shift);
        const bool closing = gap > gap_tolerance;
        double     step = 1., trial = 0.;
        if (trust_region && !closing)
          {
            const TrustRegionStep iteration = trust_region_step(
              radius, forcing, target, !reuse_tangent, nodal_forces);
            reuse_tangent = !iteration.accepted;
            report.linear_iterations += iteration.update.iterations;
            if (first_radius == 0.)
              first_radius = radius;
            // only a Newton step (inside the region) counts as one
            if (iteration.update.on_boundary || !iteration.accepted)
              ++continuation_iterations;
            else
              ++newton_iterations;
            if (verbose)
              pcout << "    trust region: step " << std::setprecision(3)
                    << iteration.update.step_norm << " ("
                    << (iteration.update.negative_curvature ?
                          "negative curvature, " :
                          "")
                    << (iteration.update.on_boundary ? "on the boundary" :
                                                       "inside")
                    << ", " << iteration.update.iterations
                    << " CG), energy decrease / predicted " << iteration.ratio
                    << (iteration.accepted ? "" : ", rejected")
                    << "; radius now " << radius << std::endl;
            if (!iteration.accepted)
              {
                if (iteration.update.preconditioner_indefinite &&
                    iteration.update.step_norm == 0.)
                  {
                    report.failure = "the preconditioner is not positive "
                                     "definite (trust-region step)";
                    return report;
                  }
                if (radius < 1e-10 * first_radius)
                  {
                    report.failure = "the trust region collapsed";
                    return report;
                  }
                continue;
              }
            trial = iteration.residual;
          }
        else
          {
            try
              {
                // An update CG could not bring to its target is still an
                // inexact Newton step if it has reduced the residual by the
                // acceptable forcing term, or if its linearised residual is
                // already within Newton's tolerance (near the solution CG's
                // own target, a tenth of that, can lie below what it reaches
                // on an ill-conditioned tangent).
                const double rhs_norm = elasticity.get_system_rhs().l2_norm();
                const LinearSolveReport linear = elasticity.solve_newton_update(
                  forcing,
                  0.1 * target,
                  std::max(inexact ?
                             parameters.acceptable_forcing_term * rhs_norm :
                             0.,
                           target));
                report.linear_iterations += linear.iterations;
                if (!linear.reached_target && verbose)
                  pcout << "    (CG stopped at its iteration limit, relative "
                           "residual "
                        << std::setprecision(3)
                        << linear.final_residual / rhs_norm << ")" << std::endl;
              }
            catch (const ExceptionBase &e)
              {
                std::ostringstream message;
                e.print_info(message);
                report.failure = "the linear solver failed (" +
                                 Utilities::trim(message.str()) + ")";
                report.linear_failure_at_start = report.iterations == 0;
                return report;
              }
            elasticity.store_solution();
            if (shift > 0)
              {
                // Continuation with the shifted tangent K + shift D, which is
                // positive definite for a large enough shift where K is not. On
                // the energy (Levenberg-Marquardt): the line search takes a
                // step along the (descending) update; a whole step halves the
                // shift, a shortened one doubles it. Otherwise pseudo-transient
                // continuation: the whole step, the shift following the
                // residual (switched evolution relaxation). Either way, no
                // descent (or inverted cells) multiplies the shift by ten, and
                // Newton's method takes over again once the residual has
                // dropped tenfold (on the energy also once the shift has
                // become small).
                const bool on_energy =
                  parameters.line_search == LineSearch::energy;
                ++continuation_iterations;
                LineSearchResult search{true, 1., 0.};
                if (on_energy)
                  search = energy_line_search(target, nodal_forces);
                else
                  {
                    elasticity.set_solution_from_stored(1.);
                    search.residual =
                      elasticity.assemble_newton_system(false, nodal_forces);
                    search.accepted = std::isfinite(search.residual);
                  }
                if (!search.accepted)
                  {
                    elasticity.restore_solution();
                    shift *= 10.;
                    continue;
                  }
                step  = search.step;
                trial = search.residual;
                shift *= on_energy ? (step == 1. ? 0.5 : 2.) : trial / residual;
                last_shift = shift;
                if (trial < 0.1 * continuation_start ||
                    (on_energy && shift < 1e-3 * parameters.continuation_shift))
                  shift = 0.;
              }
            else
              {
                ++newton_iterations;
                // A step that reaches the prescribed displacements is taken
                // whole; otherwise the line search chooses it.
                LineSearchResult search{true, 1., 0.};
                if (closing || parameters.line_search == LineSearch::none)
                  {
                    elasticity.set_solution_from_stored(1.);
                    search.residual =
                      elasticity.assemble_newton_system(false, nodal_forces);
                  }
                else
                  search =
                    parameters.line_search == LineSearch::energy ?
                      energy_line_search(target, nodal_forces) :
                      residual_line_search(residual, target, nodal_forces);
                step  = search.step;
                trial = search.residual;
                if (!search.accepted)
                  {
                    elasticity.restore_solution();
                    if (forcing > 0.)
                      {
                        // an inexact update may be what fails: solve it again,
                        // accurately
                        forcing = 0.;
                        continue;
                      }
                    // a limit or bifurcation point shows as negative curvature
                    const double curvature =
                      elasticity.newton_update_curvature();
                    if (!continuation_exhausted())
                      {
                        // past a stability limit Newton's direction need not
                        // lower the residual: continue with trust-region
                        // steps or with a shifted tangent
                        if (parameters.globalisation == Globalisation::hybrid)
                          trust_region = true;
                        else
                          {
                            shift              = last_shift > 0 ?
                                                   last_shift :
                                                   parameters.continuation_shift;
                            continuation_start = residual;
                          }
                        if (verbose)
                          {
                            pcout << "    line search failed (du.K du/du.du = "
                                  << std::setprecision(3) << curvature << "): "
                                  << (trust_region ?
                                        "trust-region steps" :
                                        "pseudo-transient continuation")
                                  << std::endl;
                            if (curvature < 0)
                              pcout << "    unstable direction: "
                                    << elasticity.describe_newton_update()
                                    << std::endl;
                          }
                        continue;
                      }
                    report.failure =
                      std::isfinite(trial) ?
                        (parameters.line_search == LineSearch::energy ?
                           "the line search found no decrease of the energy" :
                           "the line search found no decrease of the residual") :
                        "every step of the line search inverts cells";
                    if (curvature < 0)
                      {
                        std::ostringstream text;
                        text << "; the tangent is indefinite along the Newton "
                                "direction (du.K du/du.du = "
                             << std::setprecision(3) << curvature << ")";
                        report.failure += text.str();
                      }
                    return report;
                  }
              }
          }
        ++report.iterations;
        if (inexact)
          forcing = eisenstat_walker(forcing, trial / residual);
        residual = trial;
        gap      = elasticity.dirichlet_gap();
        report.residuals.push_back(residual);
        if (verbose)
          pcout << "    " << (shift > 0 ? "Continuation" : "Newton")
                << " iteration " << report.iterations << ": residual "
                << std::scientific << std::setprecision(3) << residual
                << std::defaultfloat
                << (step < 1. ? ", step " + std::to_string(step) :
                                std::string())
                << (shift > 0 ? ", shift " + std::to_string(shift) :
                                std::string())
                << std::endl;
        if (!std::isfinite(residual))
          {
            report.failure = "inverted cells";
            return report;
          }
        if (closing && gap <= gap_tolerance)
          target = std::max(parameters.absolute_tolerance,
                            parameters.relative_tolerance *
                              std::max(residual, load_scale));
      }
    report.converged = true;
    return report;
  }


  LoadPathReport
  NewtonSolver::follow(
    const double         from,
    const double         to,
    double              &increment,
    const std::function<std::vector<std::pair<types::global_dof_index, double>>(
      double)>          &apply_load,
    const LoadDependence load_dependence)
  {
    LoadPathReport report;
    const double   path     = to - from;
    double         position = from;
    increment               = std::min(increment, path);
    unsigned int increments = 0;
    while (position < to - 1e-12 * std::abs(path))
      {
        AssertThrow(increments < parameters.max_increments,
                    ExcMessage("Newton's method: the load step from " +
                               std::to_string(from) + " to " +
                               std::to_string(to) + " has reached only " +
                               std::to_string(position) + " after " +
                               std::to_string(increments) +
                               " increments (Nonlinear solver/Max "
                               "increments): the solve crawls."));
        ++increments;
        const double       next         = std::min(position + increment, to);
        const auto         start        = elasticity.get_solution();
        const auto         nodal_forces = apply_load(next);
        const NewtonReport newton       = solve(nodal_forces);
        report.newton_iterations += newton.iterations;
        report.linear_iterations += newton.linear_iterations;
        if (newton.converged)
          {
            position = next;
            ++report.steps;
            report.last_residuals = newton.residuals;
            if (verbose)
              pcout << "  load " << std::setprecision(6) << position << ": "
                    << newton.iterations << " Newton iterations" << std::endl;
            if (newton.iterations <= parameters.easy_iterations)
              increment *= parameters.growth_factor;
          }
        else
          {
            // The first update of an increment solves with the tangent of
            // the converged state and a right-hand side that scales with
            // the increment: if CG fails on it, it fails on any smaller
            // increment too (the absolute floors of its tolerance lie far
            // below the smallest increment allowed), and cutting would only
            // crawl.
            AssertThrow(!(newton.linear_failure_at_start &&
                          load_dependence == LoadDependence::right_hand_side),
                        ExcMessage(
                          "Newton's method failed at load " +
                          std::to_string(position) + " (" + newton.failure +
                          ") on the first update of the increment. Its "
                          "tangent is that of the converged state whatever "
                          "the increment, so a smaller increment cannot "
                          "help. (Poisson's ratios near 0.5 make the "
                          "tangent hard for the AMG-preconditioned CG.)"));
            // back to the last converged state, with half the increment
            elasticity.set_solution(start);
            apply_load(position);
            ++report.cuts;
            increment *= 0.5;
            pcout << "  load increment to " << std::setprecision(6) << next
                  << " rejected (" << newton.failure << "), cut to "
                  << increment << std::endl;
            AssertThrow(increment >=
                          parameters.minimum_increment * std::abs(path),
                        ExcMessage("Newton's method failed at load " +
                                   std::to_string(position) + " (" +
                                   newton.failure +
                                   ") and the increment fell below Nonlinear "
                                   "solver/Minimum increment."));
          }
      }
    return report;
  }
} // namespace ssc
