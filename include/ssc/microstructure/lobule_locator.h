#ifndef ssc_microstructure_lobule_locator_h
#define ssc_microstructure_lobule_locator_h

#include <deal.II/base/point.h>

#include <memory>

#include <ssc/mesh/layer_stack.h>
#include <ssc/microstructure/lobules.h>

namespace ssc
{
  using namespace dealii;

  /**
   * Finds the lobule that holds a point of an adipose layer. The lobules
   * are Voronoi cells in the layer's reference box (x, y, s), so the lobule
   * of a physical point is the one of the nearest generator after mapping
   * the point back, s = S (z + depth of the layer's bottom) / t(x, y); an
   * R-tree of the generators answers the query in logarithmic time.
   */
  class LobuleLocator
  {
  public:
    /// @p lobules must outlive the locator.
    LobuleLocator(const LayerStack &layers, const LayerLobules &lobules);

    ~LobuleLocator();

    /// The index into lobules.lobules of the lobule holding @p p (a point
    /// of the layer), or numbers::invalid_unsigned_int where that lobule
    /// lies outside the region of interest.
    unsigned int
    lobule_at(const Point<3> &p) const;

  private:
    const LayerStack   &layers;
    const LayerLobules &lobules;
    /// Hides the boost::geometry R-tree type from the header.
    struct Tree;
    std::unique_ptr<Tree> tree;
  };
} // namespace ssc

#endif
