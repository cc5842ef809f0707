#include <ssc/materials/corotational_material.h>
#include <ssc/materials/layer_materials.h>
#include <ssc/materials/linear_elastic_material.h>
#include <ssc/materials/neo_hookean_material.h>

namespace ssc
{
  std::unique_ptr<const Material>
  make_material(const Layer &layer)
  {
    const IsotropicModuli moduli(layer.youngs_modulus, layer.poisson_ratio);
    switch (layer.model)
      {
        case MaterialModel::linear:
          return std::make_unique<LinearElasticMaterial>(moduli);
        case MaterialModel::corotational:
          return std::make_unique<CorotationalMaterial>(
            moduli, layer.volumetric_energy);
        case MaterialModel::neo_hookean:
          return std::make_unique<NeoHookeanMaterial>(moduli,
                                                      layer.volumetric_energy);
      }
    AssertThrow(false, ExcMessage("Unknown material model."));
    return nullptr;
  }


  LayerMaterials::LayerMaterials(const LayerStack &layers)
  {
    for (unsigned int l = 0; l < layers.n_layers(); ++l)
      materials.push_back(make_material(layers.layer(l)));
  }


  bool
  LayerMaterials::any_finite_strain() const
  {
    for (const auto &material : materials)
      if (material->kinematics() == Kinematics::finite_strain)
        return true;
    return false;
  }
} // namespace ssc
