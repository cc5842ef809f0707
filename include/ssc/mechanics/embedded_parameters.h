#ifndef ssc_mechanics_embedded_parameters_h
#define ssc_mechanics_embedded_parameters_h

#include <deal.II/base/parameter_handler.h>

namespace ssc
{
  using namespace dealii;

  /// Material and quadrature of the embedded septa (membranes) and skin
  /// ligaments (cables), section "Embedded".
  struct EmbeddedParameters
  {
    bool         septa_stiffness         = true;
    double       septum_youngs_modulus   = 0.1;
    double       septum_poisson_ratio    = 0.3;
    double       septum_thickness        = 0.1;
    unsigned int septum_quadrature       = 2;
    bool         septum_tension_field    = false;
    bool         ligament_stiffness      = true;
    double       ligament_youngs_modulus = 0.1;
    double       ligament_diameter       = 0.3;
    unsigned int ligament_quadrature     = 2;
    bool         ligament_tension_only   = false;
    /// Fibrotic shortening c of the ligaments: stress-free at (1 - c) times
    /// their reference length.
    double ligament_contraction = 0;

    /// Cross-section area of a ligament, mm^2.
    double
    ligament_area() const;

    /// Declares section "Embedded", bound to the members.
    void
    add_parameters(ParameterHandler &prm);

    /// Checks the values (after parsing); throws naming the parameter.
    void
    check() const;
  };
} // namespace ssc

#endif
