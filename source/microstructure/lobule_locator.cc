#include <deal.II/base/exceptions.h>

#include <deal.II/numerics/rtree.h>

#include <utility>
#include <vector>

#include <ssc/microstructure/lobule_locator.h>

namespace ssc
{
  struct LobuleLocator::Tree
  {
    RTree<std::pair<Point<3>, unsigned int>> rtree;
  };


  LobuleLocator::LobuleLocator(const LayerStack   &layers,
                               const LayerLobules &lobules)
    : layers(layers)
    , lobules(lobules)
    , tree(std::make_unique<Tree>())
  {
    AssertThrow(!lobules.sites.empty() && lobules.reference_height > 0,
                ExcMessage("LobuleLocator: the layer has no lobules."));
    std::vector<std::pair<Point<3>, unsigned int>> sites;
    for (unsigned int i = 0; i < lobules.sites.size(); ++i)
      sites.emplace_back(lobules.sites[i], i);
    tree->rtree = pack_rtree(sites);
  }


  LobuleLocator::~LobuleLocator() = default;


  unsigned int
  LobuleLocator::lobule_at(const Point<3> &p) const
  {
    const unsigned int l      = lobules.layer;
    const double       bottom = layers.depth_of_interface(l + 1, p[0], p[1]);
    const double       t      = layers.layer(l).thickness(p[0], p[1]);
    const Point<3>     reference(p[0],
                             p[1],
                             lobules.reference_height * (p[2] + bottom) / t);
    std::vector<std::pair<Point<3>, unsigned int>> nearest;
    tree->rtree.query(boost::geometry::index::nearest(reference, 1),
                      std::back_inserter(nearest));
    AssertThrow(nearest.size() == 1, ExcInternalError());
    return lobules.site_lobule[nearest[0].second];
  }
} // namespace ssc
