#include <ssc/mechanics/embedded_parameters.h>

#include <cmath>

namespace ssc
{
  double
  EmbeddedParameters::ligament_area() const
  {
    return M_PI * ligament_diameter * ligament_diameter / 4.;
  }


  void
  EmbeddedParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Embedded");
    prm.enter_subsection("Septa");
    prm.declare_entry("Stiffness",
                      "true",
                      Patterns::Bool(),
                      "Couple the septa (the walls between the lobules, when "
                      "Microstructure/Lobules is on) to the background mesh "
                      "as embedded plane-stress membranes; false keeps them "
                      "as geometry only.");
    prm.declare_entry("Young's modulus",
                      "0.1",
                      Patterns::Double(0),
                      "Young's modulus of the septa (retinacula cutis), MPa; "
                      "Herlin et al. 2014 used 100 kPa.");
    prm.declare_entry("Poisson's ratio",
                      "0.3",
                      Patterns::Double(-1, 0.5),
                      "In-plane Poisson's ratio of the septa (plane stress).");
    prm.declare_entry("Thickness",
                      "0.1",
                      Patterns::Double(0),
                      "Thickness t of a septum, mm (histology: 20-200 um).");
    prm.declare_entry("Tension field",
                      "false",
                      Patterns::Bool(),
                      "A compressed septum wrinkles instead of carrying "
                      "compression (tension-field theory, Pipkin's relaxed "
                      "membrane energy): taut, wrinkled (uniaxial tension) "
                      "or slack. Finite strain, i.e. with a nonlinear layer "
                      "model, only; it keeps Newton's tangent positive "
                      "semi-definite where compressed septa would buckle.");
    prm.declare_entry("Quadrature points",
                      "2",
                      Patterns::Integer(1, 4),
                      "Gauss points per direction on each piece of a septum "
                      "triangle inside one background cell (1, 2, 3, 4 give "
                      "1, 3, 6, 7 points).");
    prm.leave_subsection();
    prm.enter_subsection("Ligaments");
    prm.declare_entry("Stiffness",
                      "true",
                      Patterns::Bool(),
                      "Couple the skin ligaments (when Microstructure/"
                      "Ligaments is on) as embedded axial cables.");
    prm.declare_entry("Young's modulus",
                      "0.1",
                      Patterns::Double(0),
                      "Young's modulus of the ligaments, MPa (Herlin et al. "
                      "2014: 100 kPa for the retinacula).");
    prm.declare_entry("Diameter",
                      "0.3",
                      Patterns::Double(0),
                      "Diameter of a ligament, mm (retinacular bands are "
                      "0.2-0.6 mm wide on ultrasound); the axial stiffness "
                      "is E pi d^2 / 4.");
    prm.declare_entry("Tension only",
                      "false",
                      Patterns::Bool(),
                      "A compressed ligament is slack and carries no force "
                      "(finite strain, i.e. with a nonlinear layer model, "
                      "only).");
    prm.declare_entry("Quadrature points",
                      "2",
                      Patterns::Integer(1, 6),
                      "Gauss points on each piece of a ligament segment "
                      "inside one background cell.");
    prm.leave_subsection();
    prm.leave_subsection();
  }


  void
  EmbeddedParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Embedded");
    prm.enter_subsection("Septa");
    septa_stiffness       = prm.get_bool("Stiffness");
    septum_youngs_modulus = prm.get_double("Young's modulus");
    septum_poisson_ratio  = prm.get_double("Poisson's ratio");
    septum_thickness      = prm.get_double("Thickness");
    septum_quadrature     = prm.get_integer("Quadrature points");
    septum_tension_field  = prm.get_bool("Tension field");
    prm.leave_subsection();
    prm.enter_subsection("Ligaments");
    ligament_stiffness      = prm.get_bool("Stiffness");
    ligament_youngs_modulus = prm.get_double("Young's modulus");
    ligament_diameter       = prm.get_double("Diameter");
    ligament_quadrature     = prm.get_integer("Quadrature points");
    ligament_tension_only   = prm.get_bool("Tension only");
    prm.leave_subsection();
    prm.leave_subsection();
    AssertThrow(septum_poisson_ratio > -1 && septum_poisson_ratio < 0.5,
                ExcMessage("Embedded/Septa/Poisson's ratio must lie in "
                           "(-1, 0.5)."));
  }
} // namespace ssc
