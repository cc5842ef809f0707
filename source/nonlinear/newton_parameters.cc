#include <deal.II/base/exceptions.h>

#include <sstream>

#include <ssc/nonlinear/newton_parameters.h>

namespace ssc
{
  void
  NewtonParameters::add_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Nonlinear solver");
    add_convergence_parameters(prm);
    add_globalisation_parameters(prm);
    add_load_stepping_parameters(prm);
    add_continuation_parameters(prm);
    add_forcing_term_parameters(prm);
    prm.leave_subsection();
  }


  void
  NewtonParameters::add_convergence_parameters(ParameterHandler &prm)
  {
    prm.add_parameter("Max iterations",
                      max_iterations,
                      "Newton iterations per load increment before the "
                      "increment counts as failed and is cut.",
                      Patterns::Integer(1, 1000));
    prm.add_parameter("Relative tolerance",
                      relative_tolerance,
                      "Newton stops when the residual norm is below this "
                      "factor times the scale of the load: its value at "
                      "the start of the increment or the norm of the "
                      "applied forces, whichever is larger (a cut "
                      "increment is not asked for more absolute accuracy "
                      "than the whole load)...",
                      Patterns::Double(0, 1));
    prm.add_parameter("Absolute tolerance",
                      absolute_tolerance,
                      "... or is below this value (N).",
                      Patterns::Double(0));
  }


  void
  NewtonParameters::add_globalisation_parameters(ParameterHandler &prm)
  {
    prm.add_parameter(
      "Line search",
      line_search,
      "How long a Newton step is. energy: near the minimum of the energy "
      "along the update, found from its slope r.du (regula falsi; every "
      "law, the loads and the contact are conservative); residual: "
      "halved until the residual norm decreases; none: the whole step. "
      "Both searches back off from inverted cells.");
    prm.add_parameter(
      "Globalisation",
      globalisation,
      "How Newton's method reaches a solution from far away. line search: "
      "the Line search along each update, and where it finds no decrease "
      "(past a stability limit, where the tangent is indefinite) the "
      "pseudo-transient continuation. trust region: every update is a "
      "trust-region step, the model g.p + p.K p/2 minimised by Steihaug-"
      "Toint truncated CG within a radius in the AMG preconditioner's "
      "norm, which follows directions of negative curvature to the "
      "radius, accepted if the energy (integrated from the residual by "
      "Simpson's rule) falls by at least 5 % of the model's prediction; "
      "the radius shrinks after poor steps and grows after good ones on "
      "its boundary. hybrid (the default, the most robust on the forearm "
      "indentation and the hard cases of benchmarks/): the line search, "
      "and trust-region steps for the rest of the increment once it has "
      "found no decrease. Trust-"
      "region steps that end on the radius or are rejected count against "
      "Continuation iterations, the others (Newton steps) against Max "
      "iterations. While prescribed displacements are still to be "
      "reached, every update is a Newton step.");
    prm.add_parameter("Max line search steps",
                      max_line_search,
                      "Trial steps of the line search before it gives up.",
                      Patterns::Integer(1, 50));
  }


  void
  NewtonParameters::add_load_stepping_parameters(ParameterHandler &prm)
  {
    prm.add_parameter("Initial steps",
                      initial_steps,
                      "The first increment is 1/(this) of the way to the "
                      "first target load.",
                      Patterns::Integer(1, 10000));
    prm.add_parameter("Minimum increment",
                      minimum_increment,
                      "Smallest increment, as a fraction of the way to the "
                      "current target, before the solve is given up with an "
                      "error.",
                      Patterns::Double(0, 1));
    prm.add_parameter("Max increments",
                      max_increments,
                      "Increments, converged or cut, per load step before "
                      "the solve is given up with an error: a solve that "
                      "crawls in tiny increments stops instead of running "
                      "for hours. At least Initial steps.",
                      Patterns::Integer(1));
    prm.add_parameter("Growth factor",
                      growth_factor,
                      "Factor by which the increment grows after an easy "
                      "increment.",
                      Patterns::Double(1, 10));
    prm.add_parameter(
      "Predictor",
      predictor,
      "Where Newton's method starts an increment. none: at the last "
      "converged state. extrapolation: at the last converged state plus "
      "the last converged increment's change, scaled by the ratio of the "
      "load increments (a secant predictor; dropped where it inverts a "
      "cell and, where only loads changed, unless it lowers the residual "
      "norm). The first increment starts at the converged state either "
      "way.");
    prm.add_parameter("Easy iterations",
                      easy_iterations,
                      "An increment that converged in at most this many "
                      "Newton iterations is easy.",
                      Patterns::Integer(1, 100));
  }


  void
  NewtonParameters::add_continuation_parameters(ParameterHandler &prm)
  {
    prm.add_parameter(
      "Continuation iterations",
      continuation_iterations,
      "With Globalisation = line search: when the line search finds no "
      "decrease (past a stability limit, where the tangent is "
      "indefinite), Newton's method continues with the tangent shifted by "
      "a multiple of its diagonal (pseudo-transient continuation) for at "
      "most this many iterations per increment; 0 turns it off and cuts "
      "the increment instead. With trust-region steps (trust region, "
      "hybrid), the most steps per increment that end on the radius or are "
      "rejected.",
      Patterns::Integer(0, 10000));
    prm.add_parameter("Continuation shift",
                      continuation_shift,
                      "First shift of the pseudo-transient continuation "
                      "(Globalisation = line search), as "
                      "a multiple of the tangent's diagonal; it then "
                      "follows the residual (switched evolution "
                      "relaxation). Newton's method takes over again once "
                      "the residual has dropped tenfold.",
                      Patterns::Double(0));
  }


  void
  NewtonParameters::add_forcing_term_parameters(ParameterHandler &prm)
  {
    prm.add_parameter(
      "Forcing term",
      forcing_term,
      "How accurately each Newton update is solved. fixed: to "
      "Elasticity/Linear solver/Tolerance relative to the residual, every "
      "time. Eisenstat-Walker (inexact Newton, their second choice): to "
      "eta times the residual, eta = 0.9 (r_k/r_{k-1})^2, at most Max "
      "forcing term and at least the linear solver's tolerance: loose far "
      "from the solution, where an accurate update is wasted work, tight "
      "near it, so that the convergence stays quadratic.");
    prm.add_parameter("Max forcing term",
                      max_forcing_term,
                      "Largest relative tolerance of a Newton update with "
                      "the Eisenstat-Walker forcing term (also that of the "
                      "first update of every increment).",
                      Patterns::Double(0, 0.5));
    prm.add_parameter(
      "Acceptable forcing term",
      acceptable_forcing_term,
      "A Newton update that CG could not bring to its target within "
      "Elasticity/Linear solver/Max iterations is still taken if CG has "
      "reduced its residual by this factor (an inexact Newton step: the "
      "nonlinear residual then still contracts by about this factor) or "
      "has met Newton's own tolerance; otherwise the increment fails. "
      "Nearly incompressible layers (Poisson's ratio 0.4999) make CG "
      "stall at a few per cent. With the fixed forcing term only Newton's "
      "tolerance counts. At least Max forcing term.",
      Patterns::Double(0, 0.9));
  }


  void
  NewtonParameters::check() const
  {
    const auto text = [](const double value) {
      std::ostringstream out;
      out << value;
      return out.str();
    };
    AssertThrow(acceptable_forcing_term >= max_forcing_term,
                ExcMessage("Nonlinear solver/Acceptable forcing term (" +
                           text(acceptable_forcing_term) +
                           ") must be at least Max forcing term (" +
                           text(max_forcing_term) + ")."));
    AssertThrow(continuation_iterations == 0 || continuation_shift > 0,
                ExcMessage("Nonlinear solver/Continuation shift must be "
                           "positive when Continuation iterations is not 0."));
    AssertThrow(max_increments >= initial_steps,
                ExcMessage("Nonlinear solver/Max increments (" +
                           std::to_string(max_increments) +
                           ") must be at least Initial steps (" +
                           std::to_string(initial_steps) + ")."));
  }
} // namespace ssc
