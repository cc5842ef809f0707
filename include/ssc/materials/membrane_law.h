#ifndef ssc_materials_membrane_law_h
#define ssc_materials_membrane_law_h

#include <deal.II/base/tensor.h>

#include <utility>

#include <ssc/materials/isotropic_moduli.h>
#include <ssc/materials/material.h>

namespace ssc
{
  using namespace dealii;

  /**
   * The law of a membrane (a septum) of thickness t, per unit reference
   * area: plane stress in the tangent plane, no bending.
   *
   * Small strain (projector P = I - n n onto the tangent plane, eps_m =
   * P eps P): W = (t/2) (lambda_ps tr(eps_m)^2 + 2 mu eps_m : eps_m),
   * lambda_ps = E nu / (1 - nu^2). Finite strain: the same on the membrane
   * Green-Lagrange strain E = (P F^T F P - P) / 2 (St Venant-Kirchhoff),
   * optionally as a tension field (Pipkin's relaxed energy): a membrane
   * cannot carry compression, it wrinkles.
   */
  class MembraneLaw
  {
  public:
    MembraneLaw(const IsotropicModuli &moduli,
                const double           thickness,
                const bool             tension_field);

    /// Taut, wrinkled or slack (tension-field theory).
    enum class Regime
    {
      taut,
      wrinkled,
      slack
    };

    /// The stress and second derivative of the energy at one point, both
    /// scaled by a weight (JxW).
    struct State
    {
      Regime       regime = Regime::taut;
      Tensor<2, 3> stress; ///< weight dW/dE (second Piola, in the plane)
      double       lambda = 0, two_mu = 0;
      /// wrinkled: uniaxial modulus, principal strains and directions
      double       youngs = 0, E1 = 0, E2 = 0;
      Tensor<1, 3> n1, n2;

      /// weight d2W/dE2 [A, B] for tangential strain variations A, B.
      double
      second_derivative(const Tensor<2, 3> &A, const Tensor<2, 3> &B) const;
    };

    /// State at the Green strain @p E of the plane with projector @p P,
    /// scaled by @p weight.
    State
    state(const Tensor<2, 3> &E,
          const Tensor<2, 3> &P,
          const double        weight) const;

    /// t lambda_ps and 2 t mu: the small-strain coefficients per unit area.
    std::pair<double, double>
    small_strain_coefficients() const
    {
      return {t_lambda, t_two_mu};
    }

    /// von Mises stress (MPa) of the membrane's Cauchy stress at the
    /// background deformation gradient @p F, for the unit normal @p normal
    /// in the reference configuration. Finite strain: sigma = F S F^T /
    /// (t J_s), S the stress above, J_s the area stretch, the thickness
    /// taken unchanged (the membrane has none of its own); small strain:
    /// the plane stress state of eps = sym(F - I).
    double
    von_mises_stress(const Tensor<2, 3> &F,
                     const Tensor<1, 3> &normal,
                     const Kinematics    kinematics) const;

    /// Two orthonormal vectors of the plane normal to the unit vector
    /// @p normal.
    static std::pair<Tensor<1, 3>, Tensor<1, 3>>
    tangent_basis(const Tensor<1, 3> &normal);

  private:
    const double thickness;
    const double t_lambda, t_two_mu;
    const bool   tension_field;
  };
} // namespace ssc

#endif
