#ifndef ssc_mechanics_corotational_material_h
#define ssc_mechanics_corotational_material_h

#include <deal.II/base/tensor.h>

#include <ssc/mechanics/volumetric_energy.h>

namespace ssc
{
  using namespace dealii;

  /**
   * Corotational linear elasticity written as a hyperelastic law, so that
   * Newton's method gets an exact tangent: with the polar decomposition
   * F = R U, the small-strain energy is evaluated on the rotated strain
   * U - I (the "corotated" strain of element-based corotational codes),
   *   Psi = mu |dev(U - I)|^2 + U(J)  (U(J): VolumetricEnergy),
   * i.e. mu |dev U|^2 = mu (F:F - (tr U)^2 / 3) for the shear part, whose
   * first Piola stress is P = 2 mu (F - tr(U)/3 R) since d tr(U)/dF = R.
   * The volumetric part replaces kappa/2 (tr U - 3)^2 of the textbook form
   * by U(J): both agree to second order, and U(J) lets the same cell
   * assembly use the mean dilatation (mixed formulation) against locking
   * and keeps J > 0. The tangent needs dR: with W = R^T dR (skew, axial
   * vector w), (tr(U) I - U) w = axial(R^T dF - dF^T R) (McAdams et al.
   * 2011; Chao et al. 2010).
   */
  class CorotationalMaterial : public VolumetricEnergy
  {
  public:
    CorotationalMaterial(const double youngs_modulus,
                         const double poisson_ratio);

    /// First Piola stress @p P of the shear part and its derivative
    /// @p A = dP/dF (A[i][j][k][l] = dP_ij / dF_kl) at @p F (det F > 0).
    void
    deviatoric(const Tensor<2, 3> &F, Tensor<2, 3> &P, Tensor<4, 3> &A) const;

    /// Strain energy density per reference volume.
    double
    energy(const Tensor<2, 3> &F) const;

    /// Polar decomposition F = R U (R a rotation, U symmetric positive
    /// definite) for det F > 0.
    static void
    polar_decomposition(const Tensor<2, 3> &F,
                        Tensor<2, 3>       &R,
                        Tensor<2, 3>       &U);

    /// Shear modulus, MPa.
    const double mu;
  };
} // namespace ssc

#endif
