#ifndef ssc_mechanics_neo_hookean_material_h
#define ssc_mechanics_neo_hookean_material_h

#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <ssc/mechanics/volumetric_energy.h>

#include <cmath>

namespace ssc
{
  using namespace dealii;

  /**
   * Compressible neo-Hookean material with the isochoric/volumetric split
   *   Psi = mu/2 (J^{-2/3} I_1 - 3) + U(J)  (U: VolumetricEnergy),
   * with mu and kappa = lambda + 2 mu / 3 from (E, nu), so that it agrees
   * with linear elasticity for small strains. The isochoric part is written
   * in the spatial (Kirchhoff) form used by the cell assembly:
   *   tau_iso = mu dev(b_bar),  b_bar = J^{-2/3} F F^T,
   *   c_iso   = 2/3 mu tr(b_bar) (I^s - 1/3 1 (x) 1)
   *             - 2/3 (tau_iso (x) 1 + 1 (x) tau_iso)
   * (Holzapfel 2000, §6.6; Simo & Hughes 1998). The volumetric part is
   * VolumetricEnergy.
   */
  class NeoHookeanMaterial : public VolumetricEnergy
  {
  public:
    NeoHookeanMaterial(const double youngs_modulus, const double poisson_ratio)
      : VolumetricEnergy(youngs_modulus / (3. * (1. - 2. * poisson_ratio)))
      , mu(youngs_modulus / (2. * (1. + poisson_ratio)))
    {}

    /// Isochoric Kirchhoff stress and its spatial tangent for the
    /// deformation gradient @p F (det F > 0).
    void
    isochoric(const Tensor<2, 3>    &F,
              SymmetricTensor<2, 3> &tau,
              SymmetricTensor<4, 3> &tangent) const
    {
      const double                J = determinant(F);
      const SymmetricTensor<2, 3> b_bar =
        std::pow(J, -2. / 3.) * symmetrize(F * transpose(F));
      const SymmetricTensor<2, 3> I = unit_symmetric_tensor<3>();
      tau                           = mu * deviator(b_bar);
      tangent                       = 2. / 3. * mu * trace(b_bar) *
                  (identity_tensor<3>() - 1. / 3. * outer_product(I, I)) -
                2. / 3. * (outer_product(tau, I) + outer_product(I, tau));
    }

    /// Strain energy density per reference volume.
    double
    energy(const Tensor<2, 3> &F) const
    {
      const double J = determinant(F);
      return 0.5 * mu * (std::pow(J, -2. / 3.) * scalar_product(F, F) - 3.) +
             volumetric_energy(J);
    }

    /// Shear modulus, MPa.
    const double mu;
  };
} // namespace ssc

#endif
