#include <deal.II/base/exceptions.h>

#include <cmath>
#include <random>

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
    std::mt19937                     generator(parameters.growth_seed);
    std::uniform_real_distribution<> uniform(0., 1.);
    std::normal_distribution<>       normal(0., 1.);
    const double                     spread = parameters.lobule_growth_spread;
    for (const LayerLobules &lobules : microstructure->lobule_layers())
      if (layer_selected[lobules.layer])
        {
          LayerSelection &selection = selections[lobules.layer];
          selection.locator = std::make_unique<LobuleLocator>(layers, lobules);
          if (!lobules.lobules.empty())
            selection.first_id = lobules.lobules.front().id;
          for (const Lobule &lobule : lobules.lobules)
            {
              // both draws for every lobule, so that the fraction and the
              // spread do not reshuffle each other's draws
              const bool grows =
                uniform(generator) < parameters.growing_lobule_fraction;
              const double w =
                std::exp(spread * normal(generator) - spread * spread / 2);
              const bool inside = parameters.contains(lobule.centroid);
              lobules_in_region += inside;
              selection.weight.push_back(grows && inside ? w : 0.);
            }
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
          return selection.weight[lobule];
      }
    return parameters.contains(p) ? 1. : 0.;
  }


  double
  GrowthRegion::septum_weight(const Septum &septum) const
  {
    const LayerSelection &selection = selections[septum.layer];
    if (!layer_selected[septum.layer] || !selection.locator)
      return 0.;
    double sum = 0;
    for (const unsigned int id : septum.lobules)
      {
        AssertIndexRange(id - selection.first_id, selection.weight.size());
        sum += selection.weight[id - selection.first_id];
      }
    return sum / 2;
  }


  std::vector<double>
  GrowthRegion::lobule_weights() const
  {
    std::vector<double> weights;
    for (const LayerSelection &selection : selections)
      for (const double w : selection.weight)
        if (w > 0)
          weights.push_back(w);
    return weights;
  }
} // namespace ssc
