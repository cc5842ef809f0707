#include <ssc/mechanics/elasticity_parameters.h>

namespace ssc
{
  void
  ElasticityParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Elasticity");
    prm.declare_entry("Degree",
                      "1",
                      Patterns::Integer(1, 2),
                      "Polynomial degree p of the FE_Q^3 displacement (1 or "
                      "2).");
    prm.declare_entry(
      "Formulation",
      "displacement",
      Patterns::Selection("displacement|mixed|enhanced"),
      "displacement: standard Galerkin (locks for nu -> 0.5 with Q1). mixed: "
      "the volumetric strain is L2-projected onto discontinuous P_{p-1} "
      "polynomials on each cell (B-bar; equivalent to the Q_p-P_{p-1}^disc "
      "displacement-pressure method with the pressure condensed out), "
      "free of locking for nearly incompressible tissue. enhanced (Q1 "
      "only): mixed plus nine Wilson-Taylor incompatible modes per cell, "
      "condensed statically, against the shear locking of thin stiff layers "
      "(skin, fascia) in bending.");
    prm.declare_entry(
      "Volumetric stabilisation",
      "0",
      Patterns::Double(0, 1),
      "Finite-strain layers with Formulation = mixed: the fraction beta of "
      "the volumetric energy U(J) evaluated at the quadrature points, the "
      "rest, 1 - beta, from the cell's mean dilatation. The pure mean "
      "dilatation (beta = 0) admits spurious instabilities under large "
      "compression (Auricchio et al., CMAME 194, 2005); a small beta "
      "stiffens them; it adds no locking while beta times the bulk "
      "modulus stays below the shear modulus, beta < 3 (1 - 2 nu) / (2 (1 "
      "+ nu)) (0.02 at nu = 0.49).");
    prm.declare_entry("Sides",
                      "roller",
                      Patterns::Selection("free|roller|fixed"),
                      "Condition on the four lateral sides of the patch: "
                      "free (traction free), roller (zero normal "
                      "displacement) or fixed (zero displacement). The "
                      "bottom is always fixed.");
    prm.enter_subsection("Linear solver");
    prm.declare_entry("Tolerance",
                      "1e-8",
                      Patterns::Double(1e-16, 1),
                      "CG stops when the residual has dropped by this factor "
                      "relative to the right-hand side.");
    prm.declare_entry("Max iterations",
                      "1000",
                      Patterns::Integer(1),
                      "CG iteration limit. Reaching it is an error, but "
                      "for a Newton update whose residual is already below "
                      "Nonlinear solver/Acceptable forcing term times the "
                      "right-hand side or Newton's own tolerance: that "
                      "update is kept as an inexact step.");
    prm.declare_entry("Rigid body modes",
                      "true",
                      Patterns::Bool(),
                      "Give the AMG preconditioner the six rigid-body modes "
                      "as near-null space (true) or only the three "
                      "translations (false, for comparison).");
    prm.declare_entry("Smoothed aggregation",
                      "true",
                      Patterns::Bool(),
                      "Smooth the AMG prolongator (true: fewest CG "
                      "iterations) or use plain aggregation (false: about "
                      "35 % less memory, about 1.7 times the iterations).");
    prm.declare_entry("Aggregation threshold",
                      "1e-4",
                      Patterns::Double(0, 1),
                      "ML smoothed-aggregation drop tolerance.");
    prm.declare_entry("Smoother sweeps",
                      "2",
                      Patterns::Integer(1, 10),
                      "Chebyshev smoother sweeps per AMG level.");
    prm.leave_subsection();
    prm.leave_subsection();
  }


  void
  ElasticityParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Elasticity");
    degree                             = prm.get_integer("Degree");
    const std::string formulation_name = prm.get("Formulation");
    formulation = formulation_name == "mixed"    ? Formulation::mixed :
                  formulation_name == "enhanced" ? Formulation::enhanced :
                                                   Formulation::displacement;

    volumetric_stabilisation = prm.get_double("Volumetric stabilisation");
    const std::string s      = prm.get("Sides");
    sides                    = s == "free"  ? SideCondition::free :
                               s == "fixed" ? SideCondition::fixed :
                                              SideCondition::roller;
    prm.enter_subsection("Linear solver");
    tolerance             = prm.get_double("Tolerance");
    max_iterations        = prm.get_integer("Max iterations");
    rigid_body_modes      = prm.get_bool("Rigid body modes");
    smoothed_aggregation  = prm.get_bool("Smoothed aggregation");
    aggregation_threshold = prm.get_double("Aggregation threshold");
    smoother_sweeps       = prm.get_integer("Smoother sweeps");
    prm.leave_subsection();
    prm.leave_subsection();
    AssertThrow(formulation != Formulation::enhanced || degree == 1,
                ExcMessage("Elasticity/Formulation = enhanced (incompatible "
                           "modes) is a Q1 element: set Elasticity/Degree = "
                           "1."));
  }
} // namespace ssc
