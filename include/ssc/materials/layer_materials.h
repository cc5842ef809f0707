#ifndef ssc_materials_layer_materials_h
#define ssc_materials_layer_materials_h

#include <deal.II/base/types.h>

#include <memory>
#include <vector>

#include <ssc/materials/material.h>
#include <ssc/mesh/layer_stack.h>

namespace ssc
{
  /// The law of @p layer (its Material model, E and nu): the one place that
  /// turns a layer's parameters into a Material.
  std::unique_ptr<const Material>
  make_material(const Layer &layer);

  /**
   * The laws of all layers of a stack, indexed like the layers (the
   * background cells' material_id), built once and shared by the cell
   * kernels, the output and the scenes.
   */
  class LayerMaterials
  {
  public:
    explicit LayerMaterials(const LayerStack &layers);

    const Material &
    operator[](const types::material_id layer) const
    {
      AssertIndexRange(layer, materials.size());
      return *materials[layer];
    }

    /// Whether some layer is assembled by the finite-strain kernel.
    bool
    any_finite_strain() const;

  private:
    std::vector<std::unique_ptr<const Material>> materials;
  };
} // namespace ssc

#endif
