#ifndef ssc_scenes_scene_h
#define ssc_scenes_scene_h

#include <deal.II/base/mpi.h>

#include <ssc/scenes/parameters.h>

namespace ssc
{
  /**
   * What every scene is given: the parameters of the run and the
   * communicator of its ranks. A scene's public face is its constructor
   * (inherited from this class) and run().
   */
  class Scene
  {
  public:
    Scene(const Parameters &parameters, const MPI_Comm mpi_communicator)
      : parameters(parameters)
      , mpi_communicator(mpi_communicator)
    {}

  protected:
    const Parameters &parameters;
    MPI_Comm          mpi_communicator;
  };
} // namespace ssc

#endif
