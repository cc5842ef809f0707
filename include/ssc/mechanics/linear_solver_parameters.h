#ifndef ssc_mechanics_linear_solver_parameters_h
#define ssc_mechanics_linear_solver_parameters_h

#include <deal.II/base/parameter_handler.h>

namespace ssc
{
  using namespace dealii;

  /// CG with Trilinos ML smoothed-aggregation AMG (section
  /// "Elasticity/Linear solver").
  struct LinearSolverParameters
  {
    double       tolerance             = 1e-8;
    unsigned int max_iterations        = 1000;
    bool         rigid_body_modes      = true;
    bool         smoothed_aggregation  = true;
    double       aggregation_threshold = 1e-4;
    unsigned int smoother_sweeps       = 2;

    /// Declares subsection "Linear solver" of the current section, bound
    /// to the members.
    void
    add_parameters(ParameterHandler &prm);
  };
} // namespace ssc

#endif
