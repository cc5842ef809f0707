#include <ssc/layer_manifold.h>

#include <algorithm>
#include <cmath>

namespace ssc
{
  LayerManifold::LayerManifold(const LayerStack &layers)
    : layers(layers)
  {}


  std::unique_ptr<Manifold<3, 3>>
  LayerManifold::clone() const
  {
    return std::make_unique<LayerManifold>(layers);
  }


  Point<3>
  LayerManifold::push_forward(const Point<3> &chart_point) const
  {
    const double       x = chart_point[0], y = chart_point[1];
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
          return Point<3>(x, y, -(i + (depth - top) / t));
        top += t;
      }
    return Point<3>(x, y, 0.);
  }
} // namespace ssc
