#include <cmath>

#include <ssc/materials/neo_hookean_material.h>

namespace ssc
{
  namespace
  {
    /// b_bar = J^{-2/3} F F^T
    SymmetricTensor<2, 3>
    isochoric_left_stretch(const Tensor<2, 3> &F)
    {
      return std::pow(determinant(F), -2. / 3.) * symmetrize(F * transpose(F));
    }
  } // namespace


  SymmetricTensor<2, 3>
  NeoHookeanMaterial::isochoric_stress(const Point<3> &,
                                       const Tensor<2, 3> &F) const
  {
    Assert(determinant(F) > 0, ExcMessage("det F <= 0"));
    return reference_moduli.shear_modulus * deviator(isochoric_left_stretch(F));
  }


  void
  NeoHookeanMaterial::isochoric_response(const Point<3> &,
                                         const Tensor<2, 3>    &F,
                                         SymmetricTensor<2, 3> &tau,
                                         Tensor<4, 3>          &tangent) const
  {
    Assert(determinant(F) > 0, ExcMessage("det F <= 0"));
    const double                mu    = reference_moduli.shear_modulus;
    const SymmetricTensor<2, 3> b_bar = isochoric_left_stretch(F);
    const SymmetricTensor<2, 3> I     = unit_symmetric_tensor<3>();
    tau                               = mu * deviator(b_bar);
    const SymmetricTensor<4, 3> c =
      2. / 3. * mu * trace(b_bar) *
        (identity_tensor<3>() - 1. / 3. * outer_product(I, I)) -
      2. / 3. * (outer_product(tau, I) + outer_product(I, tau));
    for (unsigned int i = 0; i < 3; ++i)
      for (unsigned int k = 0; k < 3; ++k)
        for (unsigned int j = 0; j < 3; ++j)
          for (unsigned int l = 0; l < 3; ++l)
            tangent[i][k][j][l] = c[i][k][j][l] + (i == j ? tau[k][l] : 0.);
  }


  double
  NeoHookeanMaterial::energy(const Point<3> &, const Tensor<2, 3> &F) const
  {
    const double J = determinant(F);
    return 0.5 * reference_moduli.shear_modulus *
             (std::pow(J, -2. / 3.) * scalar_product(F, F) - 3.) +
           volumetric_energy.volumetric_energy(J);
  }


  namespace
  {
    const bool registered =
      register_material<NeoHookeanMaterial, VolumetricEnergyParameters>(
        "neo-Hookean",
        "compressible neo-Hookean, mu/2 (J^{-2/3} I_1 - 3) + U(J), with the "
        "small-strain moduli of E and nu (finite strain).");
  }
} // namespace ssc
