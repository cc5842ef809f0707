#include <deal.II/base/exceptions.h>

#include <cmath>

#include <ssc/mechanics/embedded_parameters.h>

namespace ssc
{
  double
  EmbeddedParameters::ligament_area() const
  {
    return M_PI * ligament_diameter * ligament_diameter / 4.;
  }


  void
  EmbeddedParameters::add_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Embedded");
    prm.enter_subsection("Septa");
    prm.add_parameter("Stiffness",
                      septa_stiffness,
                      "Couple the septa (the walls between the lobules, when "
                      "Microstructure/Lobules is on) to the background mesh "
                      "as embedded plane-stress membranes; false keeps them "
                      "as geometry only.");
    prm.add_parameter("Young's modulus",
                      septum_youngs_modulus,
                      "Young's modulus of the septa (retinacula cutis), MPa; "
                      "Herlin et al. 2014 used 100 kPa.",
                      Patterns::Double(0));
    prm.add_parameter("Poisson's ratio",
                      septum_poisson_ratio,
                      "In-plane Poisson's ratio of the septa (plane stress).",
                      Patterns::Double(-1, 0.5));
    prm.add_parameter("Thickness",
                      septum_thickness,
                      "Thickness t of a septum, mm (histology: 20-200 um).",
                      Patterns::Double(0));
    prm.add_parameter("Tension field",
                      septum_tension_field,
                      "A compressed septum wrinkles instead of carrying "
                      "compression (tension-field theory, Pipkin's relaxed "
                      "membrane energy): taut, wrinkled (uniaxial tension) "
                      "or slack. Finite strain, i.e. with a nonlinear layer "
                      "model, only; it keeps Newton's tangent positive "
                      "semi-definite where compressed septa would buckle.");
    prm.add_parameter("Quadrature points",
                      septum_quadrature,
                      "Gauss points per direction on each piece of a septum "
                      "triangle inside one background cell (1, 2, 3, 4 give "
                      "1, 3, 6, 7 points).",
                      Patterns::Integer(1, 4));
    prm.leave_subsection();
    prm.enter_subsection("Ligaments");
    prm.add_parameter("Stiffness",
                      ligament_stiffness,
                      "Couple the skin ligaments (when Microstructure/"
                      "Ligaments is on) as embedded axial cables.");
    prm.add_parameter("Young's modulus",
                      ligament_youngs_modulus,
                      "Young's modulus of the ligaments, MPa (Herlin et al. "
                      "2014: 100 kPa for the retinacula).",
                      Patterns::Double(0));
    prm.add_parameter("Diameter",
                      ligament_diameter,
                      "Diameter of a ligament, mm (retinacular bands are "
                      "0.2-0.6 mm wide on ultrasound); the axial stiffness "
                      "is E pi d^2 / 4.",
                      Patterns::Double(0));
    prm.add_parameter("Tension only",
                      ligament_tension_only,
                      "A compressed ligament is slack and carries no force "
                      "(finite strain, i.e. with a nonlinear layer model, "
                      "only).");
    prm.add_parameter(
      "Contraction",
      ligament_contraction,
      "Fibrotic shortening c of the ligaments: they are stress-free at "
      "(1 - c) times their length in the reference configuration, so they "
      "pull on the skin before any load (cellulite's septa are described as "
      "contracted and sclerosed; no measured value). Finite strain only.",
      Patterns::Double(0, 0.5));
    prm.add_parameter("Quadrature points",
                      ligament_quadrature,
                      "Gauss points on each piece of a ligament segment "
                      "inside one background cell.",
                      Patterns::Integer(1, 6));
    prm.leave_subsection();
    prm.leave_subsection();
  }


  void
  EmbeddedParameters::check() const
  {
    AssertThrow(septum_poisson_ratio > -1 && septum_poisson_ratio < 0.5,
                ExcMessage("Embedded/Septa/Poisson's ratio must lie in "
                           "(-1, 0.5)."));
    AssertThrow(septum_youngs_modulus > 0 && septum_thickness > 0,
                ExcMessage("Embedded/Septa/Young's modulus and Thickness "
                           "must be positive."));
    AssertThrow(ligament_youngs_modulus > 0 && ligament_diameter > 0,
                ExcMessage("Embedded/Ligaments/Young's modulus and Diameter "
                           "must be positive."));
  }
} // namespace ssc
