#ifndef ssc_scenes_growth_region_h
#define ssc_scenes_growth_region_h

#include <deal.II/base/point.h>

#include <memory>
#include <vector>

#include <ssc/mesh/layer_stack.h>
#include <ssc/microstructure/lobule_locator.h>
#include <ssc/microstructure/microstructure.h>
#include <ssc/scenes/growth_parameters.h>

namespace ssc
{
  /**
   * Which material grows, and how much: that of the selected layers, lobule
   * by lobule where the layer carries lobules (a lobule grows whole when its
   * centroid lies in the region, so an injection fills whole fat
   * compartments), point by point elsewhere. A lobule's weight is drawn
   * once (Growing lobule fraction, Lobule growth spread: lognormal of mean
   * 1), in the lobules' order, so every rank draws the same.
   */
  class GrowthRegion
  {
  public:
    /// @p microstructure may be null (no lobules); it must outlive this.
    GrowthRegion(const LayerStack       &layers,
                 const GrowthParameters &parameters,
                 const Microstructure   *microstructure);

    /// The growth weight of the material at reference point @p p of layer
    /// @p layer: its lobule's weight, 1 in the region outside lobules, 0
    /// elsewhere.
    double
    operator()(const Point<3> &p, const unsigned int layer) const;

    /// The growth weight of a septum: the mean of its two lobules' (a wall
    /// between a growing and a resting lobule grows half as much).
    double
    septum_weight(const Septum &septum) const;

    /// The weights of the lobules that grow, all layers.
    std::vector<double>
    lobule_weights() const;

    /// The lobules of the selected layers whose centroid lies in the
    /// region, growing or not (for messages).
    unsigned int
    n_lobules_in_region() const
    {
      return lobules_in_region;
    }

  private:
    /// The lobules of one selected layer and their growth weights (0: the
    /// lobule does not grow).
    struct LayerSelection
    {
      std::unique_ptr<LobuleLocator> locator;
      std::vector<double>            weight;
      /// Lobule::id of the layer's first lobule (ids run on).
      unsigned int first_id = 0;
    };

    const LayerStack           &layers;
    const GrowthParameters     &parameters;
    std::vector<bool>           layer_selected;
    std::vector<LayerSelection> selections; ///< per layer, may be empty
    unsigned int                lobules_in_region = 0;
  };
} // namespace ssc

#endif
