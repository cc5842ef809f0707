#ifndef ssc_materials_corotational_material_h
#define ssc_materials_corotational_material_h

#include <ssc/materials/material.h>
#include <ssc/materials/volumetric_energy_parameters.h>

namespace ssc
{
  /**
   * Corotational linear elasticity written as a hyperelastic law, so that
   * Newton's method gets an exact tangent: with the polar decomposition
   * F = R U, the small-strain energy is evaluated on the rotated stretch
   * (the "corotated" strain U - I of element-based corotational codes),
   * split like the neo-Hookean law into an isochoric and a volumetric part,
   *   Psi = mu |J^{-1/3} U - I|^2 + U(J)  (U(J): VolumetricEnergy).
   * To second order this is mu |dev eps|^2 + kappa/2 (tr eps)^2, the linear
   * law, and it is invariant under rotations. The split matters: with a
   * projected dilatation (mixed formulations) only the projection of J
   * enters U(J), and the textbook form mu |U - I|^2 + lambda/2 tr(U - I)^2
   * would let single quadrature points invert at finite energy (seen in the
   * indentation at 0.43 N); J^{-1/3} U makes the energy grow without bound
   * as J -> 0 at every point. The law is written in the first Piola form
   * and pushed forward; its tangent needs dR: with W = R^T dR (skew, axial
   * vector w), (tr(U) I - U) w = axial(R^T dF - dF^T R) (Chao et al. 2010;
   * McAdams et al. 2011).
   */
  class CorotationalMaterial : public Material
  {
  public:
    using Material::Material;

    /// The law of a layer with @p moduli and the @p parameters the law owns
    /// (what the MaterialRegistry makes).
    CorotationalMaterial(const IsotropicModuli            &moduli,
                         const VolumetricEnergyParameters &parameters)
      : Material(moduli, parameters.form)
    {}

    Kinematics
    kinematics() const override
    {
      return Kinematics::finite_strain;
    }

    void
    isochoric_response(const Point<3>        &X,
                       const Tensor<2, 3>    &F,
                       SymmetricTensor<2, 3> &tau,
                       Tensor<4, 3>          &tangent) const override;

    double
    energy(const Point<3> &X, const Tensor<2, 3> &F) const override;

    /// First Piola stress @p P of the isochoric part and its derivative
    /// @p A (A[i][j][k][l] = dP_ij / dF_kl) at @p F (det F > 0).
    void
    isochoric_first_piola(const Tensor<2, 3> &F,
                          Tensor<2, 3>       &P,
                          Tensor<4, 3>       &A) const;

    /// Polar decomposition F = R U (R a rotation, U symmetric positive
    /// definite) for det F > 0.
    static void
    polar_decomposition(const Tensor<2, 3> &F,
                        Tensor<2, 3>       &R,
                        Tensor<2, 3>       &U);
  };
} // namespace ssc

#endif
