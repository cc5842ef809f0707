#include <deal.II/base/numbers.h>

#include <algorithm>
#include <cmath>

#include <ssc/mesh/layer_manifold.h>

namespace ssc
{
  LayerManifold::LayerManifold(const LayerStack     &layers,
                               const DiskFittingMap &disk_map)
    : LayerManifold(layers, disk_map, LateralChart::cartesian)
  {}


  LayerManifold::LayerManifold(const LayerStack     &layers,
                               const DiskFittingMap &disk_map,
                               const LateralChart    lateral_chart)
    : ChartManifold<3, 3, 3>(lateral_chart == LateralChart::polar ?
                               Tensor<1, 3>({0., 2. * numbers::PI, 0.}) :
                               Tensor<1, 3>())
    , layers(layers)
    , disk_map(disk_map)
    , lateral_chart(lateral_chart)
  {}


  LayerManifold
  LayerManifold::polar(const LayerStack &layers)
  {
    return LayerManifold(layers, DiskFittingMap(), LateralChart::polar);
  }


  std::unique_ptr<Manifold<3, 3>>
  LayerManifold::clone() const
  {
    return std::unique_ptr<Manifold<3, 3>>(
      new LayerManifold(layers, disk_map, lateral_chart));
  }


  Point<3>
  LayerManifold::push_forward(const Point<3> &chart_point) const
  {
    const Point<2> xy =
      lateral_chart == LateralChart::polar ?
        Point<2>(chart_point[0] * std::cos(chart_point[1]),
                 chart_point[0] * std::sin(chart_point[1])) :
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
            const Point<2> chart_xy =
              lateral_chart == LateralChart::polar ?
                Point<2>(std::hypot(x, y), std::atan2(y, x)) :
                disk_map.inverse(Point<2>(x, y));
            return Point<3>(chart_xy[0], chart_xy[1], -(i + (depth - top) / t));
          }
        top += t;
      }
    return Point<3>(x, y, 0.); // not reached: the last layer always returns
  }
} // namespace ssc
