#ifndef ssc_materials_neo_hookean_material_h
#define ssc_materials_neo_hookean_material_h

#include <ssc/materials/material.h>
#include <ssc/materials/volumetric_energy_parameters.h>

namespace ssc
{
  /**
   * Compressible neo-Hookean material with the isochoric/volumetric split
   *   Psi = mu/2 (J^{-2/3} I_1 - 3) + U(J)  (U: VolumetricEnergy),
   * with mu and kappa from (E, nu), so that it agrees with linear
   * elasticity for small strains. In the spatial form
   *   tau_iso = mu dev(b_bar),  b_bar = J^{-2/3} F F^T,
   *   c_iso   = 2/3 mu tr(b_bar) (I^s - 1/3 1 (x) 1)
   *             - 2/3 (tau_iso (x) 1 + 1 (x) tau_iso),
   * and the tangent a_{ikjl} = c_{ikjl} + delta_ij tau_kl (Holzapfel 2000,
   * §6.6; Simo & Hughes 1998).
   */
  class NeoHookeanMaterial : public Material
  {
  public:
    using Material::Material;

    /// The law of a layer with @p moduli and the @p parameters the law owns
    /// (what the MaterialRegistry makes).
    NeoHookeanMaterial(const IsotropicModuli            &moduli,
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

    SymmetricTensor<2, 3>
    isochoric_stress(const Point<3> &X, const Tensor<2, 3> &F) const override;

    double
    energy(const Point<3> &X, const Tensor<2, 3> &F) const override;
  };
} // namespace ssc

#endif
