#include <deal.II/base/exceptions.h>

#include <algorithm>

#include <ssc/scenes/growth_region.h>

namespace ssc
{
  GrowthRegion::GrowthRegion(const LayerStack       &layers,
                             const GrowthParameters &parameters,
                             const Microstructure   *microstructure)
    : layers(layers)
    , parameters(parameters)
    , layer_selected(layers.n_layers(), false)
    , selections(layers.n_layers())
  {
    for (const std::string &name : parameters.layers)
      layer_selected[layers.index_of(name, "Growth/Layers")] = true;
    if (microstructure == nullptr)
      return;
    for (const LayerLobules &lobules : microstructure->lobule_layers())
      if (layer_selected[lobules.layer])
        {
          LayerSelection &selection = selections[lobules.layer];
          selection.locator = std::make_unique<LobuleLocator>(layers, lobules);
          for (const Lobule &lobule : lobules.lobules)
            selection.grows.push_back(parameters.contains(lobule.centroid));
        }
  }


  double
  GrowthRegion::operator()(const Point<3> &p, const unsigned int l) const
  {
    if (!layer_selected[l])
      return 0.;
    const LayerSelection &selection = selections[l];
    if (selection.locator)
      {
        const unsigned int lobule = selection.locator->lobule_at(p);
        if (lobule != numbers::invalid_unsigned_int)
          return selection.grows[lobule] ? 1. : 0.;
      }
    return parameters.contains(p) ? 1. : 0.;
  }


  unsigned int
  GrowthRegion::n_selected_lobules() const
  {
    unsigned int n = 0;
    for (const LayerSelection &selection : selections)
      n += std::count(selection.grows.begin(), selection.grows.end(), true);
    return n;
  }
} // namespace ssc
