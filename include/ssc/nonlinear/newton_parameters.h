#ifndef ssc_nonlinear_newton_parameters_h
#define ssc_nonlinear_newton_parameters_h

#include <deal.II/base/parameter_handler.h>

#include <array>

#include <ssc/base/enum_table.h>

namespace ssc
{
  using namespace dealii;

  /// How Newton's method chooses the length of its step.
  enum class LineSearch
  {
    none,     ///< the whole step
    residual, ///< backtracking until the residual norm decreases
    energy    ///< near the minimum of the energy along the update
  };

  constexpr std::array<std::pair<LineSearch, const char *>, 3>
  enum_table(LineSearch)
  {
    return {{{LineSearch::none, "none"},
             {LineSearch::residual, "residual"},
             {LineSearch::energy, "energy"}}};
  }

  /// How Newton's method keeps its iterates on the way to a solution.
  enum class Globalisation
  {
    line_search,  ///< a line search, the continuation where it fails
    trust_region, ///< trust-region steps (Steihaug-Toint CG) throughout
    hybrid        ///< a line search, trust-region steps where it fails
  };

  constexpr std::array<std::pair<Globalisation, const char *>, 3>
  enum_table(Globalisation)
  {
    return {{{Globalisation::line_search, "line search"},
             {Globalisation::trust_region, "trust region"},
             {Globalisation::hybrid, "hybrid"}}};
  }

  /// How accurately each Newton update is solved.
  enum class ForcingTerm
  {
    fixed,           ///< to Elasticity/Linear solver/Tolerance every time
    eisenstat_walker ///< inexact Newton: loose far from the solution
  };

  constexpr std::array<std::pair<ForcingTerm, const char *>, 2>
  enum_table(ForcingTerm)
  {
    return {{{ForcingTerm::fixed, "fixed"},
             {ForcingTerm::eisenstat_walker, "Eisenstat-Walker"}}};
  }

  /// Where Newton's method starts an increment.
  enum class Predictor
  {
    none,         ///< at the last converged state
    extrapolation ///< the last converged increment, scaled to this one
  };

  constexpr std::array<std::pair<Predictor, const char *>, 2>
  enum_table(Predictor)
  {
    return {
      {{Predictor::none, "none"}, {Predictor::extrapolation, "extrapolation"}}};
  }

  /// Newton's method and the adaptive load stepping around it (section
  /// "Nonlinear solver").
  struct NewtonParameters
  {
    unsigned int  max_iterations          = 25;
    double        relative_tolerance      = 1e-8;
    double        absolute_tolerance      = 1e-12;
    Globalisation globalisation           = Globalisation::hybrid;
    LineSearch    line_search             = LineSearch::energy;
    unsigned int  max_line_search         = 8;
    unsigned int  initial_steps           = 4;
    double        minimum_increment       = 1e-4;
    unsigned int  max_increments          = 200;
    double        growth_factor           = 1.5;
    Predictor     predictor               = Predictor::extrapolation;
    unsigned int  easy_iterations         = 4;
    unsigned int  continuation_iterations = 100;
    double        continuation_shift      = 0.1;
    ForcingTerm   forcing_term            = ForcingTerm::eisenstat_walker;
    double        max_forcing_term        = 1e-2;
    /// relative residual at which an update CG could not finish is kept
    double acceptable_forcing_term = 0.1;

    /// Declares section "Nonlinear solver", bound to the members.
    void
    add_parameters(ParameterHandler &prm);

    /// Checks the values (after parsing); throws naming the parameter.
    void
    check() const;

  private:
    /// Declares when Newton's method has converged or failed.
    void
    add_convergence_parameters(ParameterHandler &prm);

    /// Declares the line search and the trust-region globalisation.
    void
    add_globalisation_parameters(ParameterHandler &prm);

    /// Declares the adaptive load increments and their predictor.
    void
    add_load_stepping_parameters(ParameterHandler &prm);

    /// Declares the pseudo-transient continuation (and trust-region steps).
    void
    add_continuation_parameters(ParameterHandler &prm);

    /// Declares how accurately each Newton update is solved.
    void
    add_forcing_term_parameters(ParameterHandler &prm);
  };

} // namespace ssc

#endif
