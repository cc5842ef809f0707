#ifndef ssc_materials_linear_elastic_material_h
#define ssc_materials_linear_elastic_material_h

#include <ssc/materials/material.h>
#include <ssc/materials/material_registry.h>

namespace ssc
{
  /**
   * Small-strain isotropic linear elasticity,
   *   sigma = 2 mu dev(eps) + kappa tr(eps) I,  eps = sym(F - I),
   * assembled by the small-strain kernel. Its isochoric part is
   * 2 mu dev(eps) with the tangent 2 mu (I^s - 1/3 1 (x) 1) (no geometric
   * part), its volumetric energy kappa/2 tr(eps)^2.
   */
  class LinearElasticMaterial : public Material
  {
  public:
    using Material::Material;

    /// The law of a layer with @p moduli and the @p parameters the law owns
    /// (what the MaterialRegistry makes).
    LinearElasticMaterial(const IsotropicModuli      &moduli,
                          const NoMaterialParameters &parameters)
      : Material(moduli)
    {
      (void)parameters;
    }

    Kinematics
    kinematics() const override
    {
      return Kinematics::small_strain;
    }

    void
    isochoric_response(const Point<3>        &X,
                       const Tensor<2, 3>    &F,
                       SymmetricTensor<2, 3> &tau,
                       Tensor<4, 3>          &tangent) const override;

    double
    energy(const Point<3> &X, const Tensor<2, 3> &F) const override;

    SymmetricTensor<2, 3>
    cauchy_stress(const Point<3>     &X,
                  const Tensor<2, 3> &F,
                  const double        gamma = 1.) const override;
  };
} // namespace ssc

#endif
