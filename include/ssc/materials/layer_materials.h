#ifndef ssc_materials_layer_materials_h
#define ssc_materials_layer_materials_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/types.h>

#include <map>
#include <memory>
#include <string>
#include <vector>

#include <ssc/materials/material.h>
#include <ssc/materials/material_registry.h>
#include <ssc/materials/prestretched_material.h>
#include <ssc/materials/prony_series.h>
#include <ssc/mesh/layer_stack.h>

namespace ssc
{
  /**
   * The parameters every registered law owns, per layer: the subsections
   * "Layer stack/<layer>/<law>" of the prm file. Every law's subsection is
   * declared for every layer (as ASPECT declares every plugin's
   * parameters), so that switching a layer's "Material model" needs no
   * other change; the chosen law's parameters are the ones used. A layer
   * this object was not declared for (a stack built in code) gets each
   * law's defaults.
   */
  class LayerLawParameters
  {
  public:
    /// Every law's defaults (for layers that add_parameters() did not
    /// declare).
    LayerLawParameters();

    /// The handler keeps references to the members: neither copied nor
    /// moved.
    LayerLawParameters(const LayerLawParameters &) = delete;
    LayerLawParameters &
    operator=(const LayerLawParameters &) = delete;

    /// Declares, inside "Layer stack/<name>" for every name of
    /// @p layer_names, one subsection per registered law that has
    /// parameters, bound to this object; and the old place of "Volumetric
    /// energy", to name its new one.
    void
    add_parameters(ParameterHandler               &prm,
                   const std::vector<std::string> &layer_names);

    /// Forgets the declared layers (before the handler is declared anew).
    void
    clear()
    {
      per_layer.clear();
      moved_volumetric_energy.clear();
    }

    /// Throws, naming the parameter, unless every layer of @p layers names
    /// a registered law whose parameters are consistent.
    void
    check(const LayerStack &layers) const;

    /// The parameters of law @p law for the layer called @p layer.
    const MaterialParameters &
    of(const std::string &layer, const std::string &law) const;

  private:
    /// Per layer name, per law name.
    std::map<std::string,
             std::map<std::string, std::unique_ptr<MaterialParameters>>>
      per_layer;
    /// The defaults of every law (layers not declared).
    std::map<std::string, std::unique_ptr<MaterialParameters>> defaults;
    /// "Volumetric energy" given where round 2 had it, per layer.
    std::map<std::string, std::string> moved_volumetric_energy;
  };


  /// The deviatoric Prony series of @p layer (empty: elastic).
  PronySeries
  prony_series(const Layer &layer);

  /// The law of @p layer (its "Material model", E and nu) with the
  /// parameters @p laws holds for it: the one place that turns a layer's
  /// parameters into a Material.
  std::unique_ptr<Material>
  make_material(const Layer &layer, const LayerLawParameters &laws = {});

  /**
   * The laws of all layers of a stack, indexed like the layers (the
   * background cells' material_id), built once and shared by the cell
   * kernels, the output and the scenes.
   */
  class LayerMaterials
  {
  public:
    LayerMaterials(const LayerStack &layers, const LayerLawParameters &laws);

    const Material &
    operator[](const types::material_id layer) const
    {
      AssertIndexRange(layer, materials.size());
      return *materials[layer];
    }

    unsigned int
    size() const
    {
      return materials.size();
    }

    /// Whether some layer is assembled by the finite-strain kernel.
    bool
    any_finite_strain() const;

    /// Whether some layer is pre-tensioned (Layer stack/<layer>/Prestretch).
    bool
    any_prestretch() const
    {
      return !prestretched.empty();
    }

    /// Sets the pre-tensioned layers to the fraction @p f of their
    /// prestretch (PrestretchedMaterial::set_fraction()).
    void
    set_prestretch_fraction(const double f);

  private:
    std::vector<std::unique_ptr<const Material>> materials;
    /// The pre-tensioned ones among them, which the load can ramp.
    std::vector<PrestretchedMaterial *> prestretched;
  };
} // namespace ssc

#endif
