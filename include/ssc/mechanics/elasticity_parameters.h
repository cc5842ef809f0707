#ifndef ssc_mechanics_elasticity_parameters_h
#define ssc_mechanics_elasticity_parameters_h

#include <deal.II/base/parameter_handler.h>

namespace ssc
{
  using namespace dealii;

  /// Volume discretisation: pure displacement; displacement with the
  /// volumetric strain projected onto discontinuous P_{p-1} per cell
  /// (B-bar; the statically condensed Q_p-P_{p-1}^disc mixed method); or
  /// (Q1 only) that plus Wilson-Taylor incompatible modes, which remove the
  /// shear locking of thin layers in bending.
  enum class Formulation
  {
    displacement,
    mixed,
    enhanced
  };

  /// The prm spelling of @p formulation.
  inline const char *
  to_string(const Formulation formulation)
  {
    return formulation == Formulation::mixed    ? "mixed" :
           formulation == Formulation::enhanced ? "enhanced" :
                                                  "displacement";
  }

  /// How the lateral sides of the patch are held.
  enum class SideCondition
  {
    free,
    roller,
    fixed
  };

  /**
   * Discretisation, boundary conditions and linear solver of the volume
   * elasticity problem.
   */
  struct ElasticityParameters
  {
    unsigned int  degree      = 1;
    Formulation   formulation = Formulation::displacement;
    SideCondition sides       = SideCondition::roller;
    /// Finite strain, mixed: fraction of the volumetric energy taken at the
    /// quadrature points instead of from the cell's mean dilatation.
    double       volumetric_stabilisation = 0.;
    double       tolerance                = 1e-8;
    unsigned int max_iterations           = 1000;
    bool         rigid_body_modes         = true;
    bool         smoothed_aggregation     = true;
    double       aggregation_threshold    = 1e-4;
    unsigned int smoother_sweeps          = 2;

    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm);
  };
} // namespace ssc

#endif
