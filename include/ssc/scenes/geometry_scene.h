#ifndef ssc_scenes_geometry_scene_h
#define ssc_scenes_geometry_scene_h

#include <deal.II/base/mpi.h>

#include <ssc/parameters.h>

namespace ssc
{
  /**
   * Builds the layered patch (background mesh) and the procedural
   * microstructure without mechanics, and writes them: lobules.csv,
   * septa.vtu, ligaments.vtu, volume.vtu (layer ids) and summary.json with
   * lobules per layer, mean faces per lobule, septa area per unit volume per
   * layer, the ligament count and timings.
   */
  class GeometryScene
  {
  public:
    GeometryScene(const Parameters &parameters,
                  const MPI_Comm    mpi_communicator);

    void
    run();

  private:
    const Parameters &parameters;
    MPI_Comm          mpi_communicator;
  };
} // namespace ssc

#endif
