#ifndef ssc_mechanics_linear_elastic_material_h
#define ssc_mechanics_linear_elastic_material_h

#include <deal.II/base/symmetric_tensor.h>

namespace ssc
{
  using namespace dealii;

  /**
   * Small-strain isotropic linear elasticity, sigma = lambda tr(eps) I +
   * 2 mu eps. The volumetric part is split off so that the mixed
   * formulation can replace tr(eps) by its projection.
   */
  class LinearElasticMaterial
  {
  public:
    LinearElasticMaterial(const double youngs_modulus,
                          const double poisson_ratio)
      : lambda(youngs_modulus * poisson_ratio /
               ((1. + poisson_ratio) * (1. - 2. * poisson_ratio)))
      , mu(youngs_modulus / (2. * (1. + poisson_ratio)))
    {}

    /// Stress for strain @p eps with the volumetric strain @p theta
    /// (tr eps, or its projection in the mixed formulation).
    SymmetricTensor<2, 3>
    stress(const SymmetricTensor<2, 3> &eps, const double theta) const
    {
      return 2. * mu * eps + lambda * theta * unit_symmetric_tensor<3>();
    }

    const double lambda;
    const double mu;
  };

  /// von Mises equivalent stress of @p sigma.
  inline double
  von_mises(const SymmetricTensor<2, 3> &sigma)
  {
    const SymmetricTensor<2, 3> s = deviator(sigma);
    return std::sqrt(1.5 * scalar_product(s, s));
  }
} // namespace ssc

#endif
