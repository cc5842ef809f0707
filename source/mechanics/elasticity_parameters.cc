#include <deal.II/base/exceptions.h>

#include <ssc/mechanics/elasticity_parameters.h>

namespace ssc
{
  unsigned int
  ElasticityParameters::n_pressure_modes() const
  {
    switch (formulation)
      {
        case Formulation::displacement:
          return 0;
        case Formulation::mean_dilatation:
          return 1;
        case Formulation::mixed:
        case Formulation::enhanced:
          return degree == 1 ? 1 : 4;
      }
    return 0;
  }


  void
  ElasticityParameters::add_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Elasticity");
    prm.add_parameter("Degree",
                      degree,
                      "Polynomial degree p of the FE_Q^3 displacement (1 or "
                      "2).",
                      Patterns::Integer(1, 2));
    prm.add_parameter(
      "Formulation",
      formulation,
      "displacement: standard Galerkin (locks for nu -> 0.5 with Q1). "
      "mixed: the dilatation (tr eps at small strain, J at finite strain) "
      "is L2-projected onto discontinuous P_{p-1} polynomials on each cell, "
      "equivalent to the Q_p-P_{p-1}^disc displacement-pressure method with "
      "the pressure condensed out (B-bar; the three-field Hu-Washizu form "
      "at finite strain), free of locking for nearly incompressible tissue. "
      "mean dilatation: the same with the projection onto constants, "
      "Q_p-P0 (identical to mixed for Q1). enhanced (Q1 and linear layers "
      "only): mixed plus nine Wilson-Taylor incompatible modes per cell, "
      "condensed statically, against the shear locking of thin stiff layers "
      "(skin, fascia) in bending.");
    prm.add_parameter(
      "Volumetric stabilisation",
      volumetric_stabilisation,
      "Finite-strain layers with Formulation = mixed or mean dilatation: "
      "the fraction beta of the volumetric energy U(J) evaluated at the "
      "quadrature points, the rest, 1 - beta, from the projected "
      "dilatation. The pure mean dilatation (beta = 0) admits spurious "
      "instabilities under large compression (Auricchio et al., CMAME 194, "
      "2005); a small beta stiffens them; it adds no locking while beta "
      "times the bulk modulus stays below the shear modulus, beta < 3 (1 - "
      "2 nu) / (2 (1 + nu)) (0.02 at nu = 0.49).",
      Patterns::Double(0, 1));
    prm.add_parameter("Sides",
                      sides,
                      "Condition on the four lateral sides of the patch: "
                      "free (traction free), roller (zero normal "
                      "displacement) or fixed (zero displacement). The "
                      "bottom is always fixed.");
    linear_solver.add_parameters(prm);
    prm.leave_subsection();
  }


  void
  ElasticityParameters::check() const
  {
    AssertThrow(linear_solver.method != LinearSolverMethod::block ||
                  n_pressure_modes() > 0,
                ExcMessage("Elasticity/Linear solver/Method = block solves "
                           "the displacement-pressure system: it needs "
                           "Formulation = mixed, mean dilatation or "
                           "enhanced."));
    AssertThrow(linear_solver.method != LinearSolverMethod::block ||
                  volumetric_stabilisation < 1.,
                ExcMessage("Elasticity/Linear solver/Method = block needs "
                           "Volumetric stabilisation below 1 (a projected "
                           "dilatation)."));
    AssertThrow(formulation != Formulation::enhanced || degree == 1,
                ExcMessage("Elasticity/Formulation = enhanced (incompatible "
                           "modes) is a Q1 element: set Elasticity/Degree = "
                           "1."));
  }
} // namespace ssc
