#ifndef ssc_scenes_mechanics_model_h
#define ssc_scenes_mechanics_model_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>

#include <memory>

#include <ssc/mechanics/elastic_system.h>
#include <ssc/mechanics/microstructure_coupling.h>
#include <ssc/mesh/background_mesh.h>
#include <ssc/scenes/parameters.h>
#include <ssc/scenes/scene_run.h>

namespace ssc
{
  /**
   * What every mechanics scene builds before it loads the patch: the
   * background mesh, the elastic system on it (dofs distributed, no
   * boundary conditions yet) and the microstructure embedded in it, each
   * timed as its phase of docs/architecture.md §7 and reported in one progress
   * line.
   */
  class MechanicsModel
  {
  public:
    /// Builds the model of @p parameters, timed and reported by @p scene;
    /// a non-empty @p incision cuts its mesh.
    MechanicsModel(const Parameters &parameters,
                   SceneRun         &scene,
                   const Incision   &incision = Incision());

    /// The same on @p mpi_communicator, timed by @p timer, reported on
    /// @p pcout (and on @p timed_pcout what depends on timing): for models
    /// a scene builds many of (the identification's forward solves).
    MechanicsModel(const Parameters   &parameters,
                   const MPI_Comm      mpi_communicator,
                   TimerOutput        &timer,
                   ConditionalOStream &pcout,
                   ConditionalOStream &timed_pcout,
                   const Incision     &incision = Incision());

    BackgroundMesh &
    mesh()
    {
      return *background_mesh;
    }

    ElasticSystem &
    system()
    {
      return *elastic_system;
    }

    MicrostructureCoupling &
    coupling()
    {
      return *microstructure_coupling;
    }

  private:
    // built in this order, each on the one before
    std::unique_ptr<BackgroundMesh>         background_mesh;
    std::unique_ptr<ElasticSystem>          elastic_system;
    std::unique_ptr<MicrostructureCoupling> microstructure_coupling;
  };
} // namespace ssc

#endif
