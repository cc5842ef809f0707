#ifndef ssc_scenes_geometry_scene_h
#define ssc_scenes_geometry_scene_h

#include <deal.II/base/mpi.h>

#include <ssc/scenes/parameters.h>
#include <ssc/scenes/scene.h>

namespace ssc
{
  /**
   * Builds the layered patch (background mesh) and the procedural
   * microstructure without mechanics, and writes them: lobules.csv,
   * septa.vtu, ligaments.vtu, volume.vtu (layer ids) and summary.json with
   * lobules per layer, mean faces per lobule, septa area per unit volume per
   * layer, the ligament count and timings.
   */
  class GeometryScene : public Scene
  {
  public:
    using Scene::Scene;

    void
    run();
  };
} // namespace ssc

#endif
