#include <ssc/materials/linear_elastic_material.h>

namespace ssc
{
  void
  LinearElasticMaterial::isochoric_response(const Point<3> &,
                                            const Tensor<2, 3>    &F,
                                            SymmetricTensor<2, 3> &tau,
                                            Tensor<4, 3> &tangent) const
  {
    const double mu = reference_moduli.shear_modulus;
    tau = 2. * mu * deviator(symmetrize(F - unit_symmetric_tensor<3>()));
    const SymmetricTensor<4, 3> c =
      2. * mu *
      (identity_tensor<3>() -
       1. / 3. *
         outer_product(unit_symmetric_tensor<3>(), unit_symmetric_tensor<3>()));
    tangent = Tensor<4, 3>(c);
  }


  double
  LinearElasticMaterial::energy(const Point<3> &, const Tensor<2, 3> &F) const
  {
    const SymmetricTensor<2, 3> eps =
      symmetrize(F - unit_symmetric_tensor<3>());
    const SymmetricTensor<2, 3> e = deviator(eps);
    return reference_moduli.shear_modulus * scalar_product(e, e) +
           0.5 * reference_moduli.bulk_modulus * trace(eps) * trace(eps);
  }


  SymmetricTensor<2, 3>
  LinearElasticMaterial::cauchy_stress(const Point<3> &,
                                       const Tensor<2, 3> &F,
                                       const double        gamma) const
  {
    // the eigenstrain (gamma - 1)/3 I of growth
    const SymmetricTensor<2, 3> eps =
      symmetrize(F - unit_symmetric_tensor<3>());
    return 2. * reference_moduli.shear_modulus * deviator(eps) +
           reference_moduli.bulk_modulus * (trace(eps) - (gamma - 1.)) *
             unit_symmetric_tensor<3>();
  }


  namespace
  {
    const bool registered = register_material<LinearElasticMaterial>(
      "linear",
      "small-strain isotropic elasticity (sigma = 2 mu dev eps + kappa tr eps "
      "I), solved in one linear step.");
  }
} // namespace ssc
