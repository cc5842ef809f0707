#ifndef ssc_mesh_layer_manifold_h
#define ssc_mesh_layer_manifold_h

#include <deal.II/grid/manifold.h>

#include <ssc/mesh/disk_fitting_map.h>
#include <ssc/mesh/layer_stack.h>

namespace ssc
{
  /**
   * The map from the layer-reference coordinates (x, y, zeta) to physical
   * coordinates. In the chart, layer i occupies -(i+1) <= zeta <= -i; the
   * map stretches every layer to its thickness t_i(x, y):
   * z = -(depth_i(x, y) + (-zeta - i) t_i(x, y)).
   *
   * Used as the manifold of every cell, so that refinement places new
   * vertices on the layer interfaces exactly, and by the microstructure,
   * which is built in (x, y, zeta) and mapped the same way.
   *
   * Optionally the lateral coordinates first pass through a DiskFittingMap,
   * so that mesh lines follow a circle around the patch centre (a punch).
   *
   * The polar variant has the lateral chart (r, theta) instead of (x, y):
   * the o-grid's rings use it, so that refinement puts new vertices on
   * their circles.
   */
  class LayerManifold : public ChartManifold<3, 3, 3>
  {
  public:
    /// Lateral chart coordinates.
    enum class LateralChart
    {
      cartesian,
      polar
    };

    LayerManifold(const LayerStack     &layers,
                  const DiskFittingMap &disk_map = DiskFittingMap());

    /// The chart (r, theta, zeta), theta periodic.
    static LayerManifold
    polar(const LayerStack &layers);

    std::unique_ptr<Manifold<3, 3>>
    clone() const override;

    Point<3>
    pull_back(const Point<3> &space_point) const override;

    Point<3>
    push_forward(const Point<3> &chart_point) const override;

  private:
    LayerManifold(const LayerStack     &layers,
                  const DiskFittingMap &disk_map,
                  const LateralChart    lateral_chart);

    const LayerStack    &layers;
    const DiskFittingMap disk_map;
    const LateralChart   lateral_chart;
  };
} // namespace ssc

#endif
