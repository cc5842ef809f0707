#ifndef ssc_scenes_growth_scene_h
#define ssc_scenes_growth_scene_h

#include <deal.II/base/mpi.h>

#include <vector>

#include <ssc/scenes/growth_record.h>
#include <ssc/scenes/parameters.h>
#include <ssc/scenes/scene.h>
#include <ssc/scenes/surface_metrics.h>

namespace ssc
{
  /**
   * Fat growth (cellulite, aging) and fat injection (section "Growth"): the
   * selected fat takes an isotropic volumetric growth g, reached in equal
   * steps, with g such that the stress-free added volume equals the target;
   * the patch rests on its bottom, its sides held as Elasticity/Sides says,
   * the skin free. The skin elevation u_z(x, y) is sampled on a grid and
   * measured (SurfaceMetrics) after every step.
   *
   * Writes into output/<run name>/: summary.json, growth.csv (per step),
   * elevation.csv (x, y, u_z, trend at the last step), volume.pvd, septa
   * and ligament fields when the microstructure is on, parameters.prm,
   * log.txt.
   */
  class GrowthScene : public Scene
  {
  public:
    using Scene::Scene;

    GrowthResult
    run();
  };
} // namespace ssc

#endif
