#include <ssc/mechanics/newton_parameters.h>

namespace ssc
{
  void
  NewtonParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Nonlinear solver");
    prm.declare_entry("Max iterations",
                      "25",
                      Patterns::Integer(1, 1000),
                      "Newton iterations per load increment before the "
                      "increment counts as failed and is cut.");
    prm.declare_entry("Relative tolerance",
                      "1e-8",
                      Patterns::Double(0, 1),
                      "Newton stops when the residual norm is below this "
                      "factor times the scale of the load: its value at "
                      "the start of the increment or the norm of the "
                      "applied forces, whichever is larger (a cut "
                      "increment is not asked for more absolute accuracy "
                      "than the whole load)...");
    prm.declare_entry("Absolute tolerance",
                      "1e-12",
                      Patterns::Double(0),
                      "... or is below this value (N).");
    prm.declare_entry(
      "Line search",
      "energy",
      Patterns::Selection("energy|residual|none"),
      "How long a Newton step is. energy: near the minimum of the energy "
      "along the update, found from its slope r.du (regula falsi; every "
      "law, the loads and the contact are conservative); residual: "
      "halved until the residual norm decreases; none: the whole step. "
      "Both searches back off from inverted cells.");
    prm.declare_entry(
      "Globalisation",
      "hybrid",
      Patterns::Selection("line search|trust region|hybrid"),
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
    prm.declare_entry("Max line search steps",
                      "8",
                      Patterns::Integer(1, 50),
                      "Trial steps of the line search before it gives up.");
    prm.declare_entry("Initial steps",
                      "4",
                      Patterns::Integer(1, 10000),
                      "The first increment is 1/(this) of the way to the "
                      "first target load.");
    prm.declare_entry("Minimum increment",
                      "1e-4",
                      Patterns::Double(0, 1),
                      "Smallest increment, as a fraction of the way to the "
                      "current target, before the solve is given up with an "
                      "error.");
    prm.declare_entry("Max increments",
                      "200",
                      Patterns::Integer(1),
                      "Increments, converged or cut, per load step before "
                      "the solve is given up with an error: a solve that "
                      "crawls in tiny increments stops instead of running "
                      "for hours. At least Initial steps.");
    prm.declare_entry("Growth factor",
                      "1.5",
                      Patterns::Double(1, 10),
                      "Factor by which the increment grows after an easy "
                      "increment.");
    prm.declare_entry("Easy iterations",
                      "4",
                      Patterns::Integer(1, 100),
                      "An increment that converged in at most this many "
                      "Newton iterations is easy.");
    prm.declare_entry(
      "Continuation iterations",
      "100",
      Patterns::Integer(0, 10000),
      "With Globalisation = line search: when the line search finds no "
      "decrease (past a stability limit, where the tangent is "
      "indefinite), Newton's method continues with the tangent shifted by "
      "a multiple of its diagonal (pseudo-transient continuation) for at "
      "most this many iterations per increment; 0 turns it off and cuts "
      "the increment instead. With trust-region steps (trust region, "
      "hybrid), the most steps per increment that end on the radius or are "
      "rejected.");
    prm.declare_entry("Continuation shift",
                      "0.1",
                      Patterns::Double(0),
                      "First shift of the pseudo-transient continuation "
                      "(Globalisation = line search), as "
                      "a multiple of the tangent's diagonal; it then "
                      "follows the residual (switched evolution "
                      "relaxation). Newton's method takes over again once "
                      "the residual has dropped tenfold.");
    prm.declare_entry(
      "Forcing term",
      "Eisenstat-Walker",
      Patterns::Selection("fixed|Eisenstat-Walker"),
      "How accurately each Newton update is solved. fixed: to "
      "Elasticity/Linear solver/Tolerance relative to the residual, every "
      "time. Eisenstat-Walker (inexact Newton, their second choice): to "
      "eta times the residual, eta = 0.9 (r_k/r_{k-1})^2, at most Max "
      "forcing term and at least the linear solver's tolerance: loose far "
      "from the solution, where an accurate update is wasted work, tight "
      "near it, so that the convergence stays quadratic.");
    prm.declare_entry("Max forcing term",
                      "0.01",
                      Patterns::Double(0, 0.5),
                      "Largest relative tolerance of a Newton update with "
                      "the Eisenstat-Walker forcing term (also that of the "
                      "first update of every increment).");
    prm.declare_entry(
      "Acceptable forcing term",
      "0.1",
      Patterns::Double(0, 0.9),
      "A Newton update that CG could not bring to its target within "
      "Elasticity/Linear solver/Max iterations is still taken if CG has "
      "reduced its residual by this factor (an inexact Newton step: the "
      "nonlinear residual then still contracts by about this factor) or "
      "has met Newton's own tolerance; otherwise the increment fails. "
      "Nearly incompressible layers (Poisson's ratio 0.4999) make CG "
      "stall at a few per cent. With the fixed forcing term only Newton's "
      "tolerance counts. At least Max forcing term.");
    prm.leave_subsection();
  }


  void
  NewtonParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Nonlinear solver");
    max_iterations           = prm.get_integer("Max iterations");
    relative_tolerance       = prm.get_double("Relative tolerance");
    absolute_tolerance       = prm.get_double("Absolute tolerance");
    const std::string search = prm.get("Line search");
    line_search              = search == "energy"   ? LineSearch::energy :
                               search == "residual" ? LineSearch::residual :
                                                      LineSearch::none;
    const std::string globalisation_name = prm.get("Globalisation");
    globalisation           = globalisation_name == "trust region" ?
                                Globalisation::trust_region :
                              globalisation_name == "hybrid" ? Globalisation::hybrid :
                                                               Globalisation::line_search;
    max_line_search         = prm.get_integer("Max line search steps");
    initial_steps           = prm.get_integer("Initial steps");
    minimum_increment       = prm.get_double("Minimum increment");
    max_increments          = prm.get_integer("Max increments");
    growth_factor           = prm.get_double("Growth factor");
    easy_iterations         = prm.get_integer("Easy iterations");
    continuation_iterations = prm.get_integer("Continuation iterations");
    continuation_shift      = prm.get_double("Continuation shift");
    forcing_term            = prm.get("Forcing term") == "fixed" ?
                                ForcingTerm::fixed :
                                ForcingTerm::eisenstat_walker;
    max_forcing_term        = prm.get_double("Max forcing term");
    acceptable_forcing_term = prm.get_double("Acceptable forcing term");
    AssertThrow(acceptable_forcing_term >= max_forcing_term,
                ExcMessage("Nonlinear solver/Acceptable forcing term (" +
                           prm.get("Acceptable forcing term") +
                           ") must be at least Max forcing term (" +
                           prm.get("Max forcing term") + ")."));
    AssertThrow(continuation_iterations == 0 || continuation_shift > 0,
                ExcMessage("Nonlinear solver/Continuation shift must be "
                           "positive when Continuation iterations is not 0."));
    AssertThrow(max_increments >= initial_steps,
                ExcMessage("Nonlinear solver/Max increments (" +
                           std::to_string(max_increments) +
                           ") must be at least Initial steps (" +
                           std::to_string(initial_steps) + ")."));
    prm.leave_subsection();
  }
} // namespace ssc
