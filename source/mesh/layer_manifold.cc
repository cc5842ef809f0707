#include <algorithm>
#include <cmath>

#include <ssc/mesh/layer_manifold.h>

namespace ssc
{
  LayerManifold::LayerManifold(const LayerStack     &layers,
                               const DiskFittingMap &disk_map)
    : layers(layers)
    , disk_map(disk_map)
  {}


  std::unique_ptr<Manifold<3, 3>>
  LayerManifold::clone() const
  {
    return std::make_unique<LayerManifold>(layers, disk_map);
  }


  Point<3>
  LayerManifold::push_forward(const Point<3> &chart_point) const
  {
    const Point<2> xy =
      disk_map.forward(Point<2>(chart_point[0], chart_point[1]));
    const double       x = xy[0], y = xy[1];
    const double       s = std::max(0., -chart_point[2]);
    const unsigned int n = layers.n_layers();
    const unsigned int i =
      std::min(static_cast<unsigned int>(std::floor(s)), n - 1);
    const double depth = layers.depth_of_interface(i, x, y) +
                         (s - i) * layers.layer(i).thickness(x, y);
    return Point<3>(x, y, -depth);
  }


  Point<3>
  LayerManifold::pull_back(const Point<3> &space_point) const
  {
    const double       x = space_point[0], y = space_point[1];
    const double       depth = -space_point[2];
    const unsigned int n     = layers.n_layers();
    double             top   = 0;
    for (unsigned int i = 0; i < n; ++i)
      {
        const double t = layers.layer(i).thickness(x, y);
        if (depth <= top + t || i == n - 1)
          {
            const Point<2> chart_xy = disk_map.inverse(Point<2>(x, y));
            return Point<3>(chart_xy[0], chart_xy[1], -(i + (depth - top) / t));
          }
        top += t;
      }
    return Point<3>(x, y, 0.); // not reached: the last layer always returns
  }
} // namespace ssc
