#ifndef ssc_mechanics_linear_solver_parameters_h
#define ssc_mechanics_linear_solver_parameters_h

#include <deal.II/base/parameter_handler.h>

#include <array>
#include <utility>

#include <ssc/base/enum_table.h>

namespace ssc
{
  using namespace dealii;

  /// How the linear systems are solved.
  enum class LinearSolverMethod
  {
    cg,
    block,
    direct
  };

  constexpr std::array<std::pair<LinearSolverMethod, const char *>, 3>
  enum_table(LinearSolverMethod)
  {
    return {{{LinearSolverMethod::cg, "cg"},
             {LinearSolverMethod::block, "block"},
             {LinearSolverMethod::direct, "direct"}}};
  }

  /// What preconditions the displacement system (the displacement block of
  /// the block method).
  enum class DisplacementPreconditioner
  {
    amg,
    cholesky,
    ldlt,
    gmg
  };

  constexpr std::array<std::pair<DisplacementPreconditioner, const char *>, 4>
  enum_table(DisplacementPreconditioner)
  {
    return {{{DisplacementPreconditioner::amg, "amg"},
             {DisplacementPreconditioner::cholesky, "cholesky"},
             {DisplacementPreconditioner::ldlt, "ldlt"},
             {DisplacementPreconditioner::gmg, "gmg"}}};
  }

  /// Krylov solver and Trilinos ML smoothed-aggregation AMG (section
  /// "Elasticity/Linear solver").
  struct LinearSolverParameters
  {
    LinearSolverMethod         method         = LinearSolverMethod::cg;
    DisplacementPreconditioner preconditioner = DisplacementPreconditioner::amg;
    unsigned int               refactorization_iterations = 20;
    bool                       factor_indefinite          = true;
    bool                       keep_vcycle                = false;
    double                     tolerance                  = 1e-8;
    unsigned int               max_iterations             = 1000;
    bool                       rigid_body_modes           = true;
    bool                       smoothed_aggregation       = true;
    double                     aggregation_threshold      = 1e-4;
    unsigned int               smoother_sweeps            = 2;

    /// Declares subsection "Linear solver" of the current section, bound
    /// to the members.
    void
    add_parameters(ParameterHandler &prm);
  };
} // namespace ssc

#endif
