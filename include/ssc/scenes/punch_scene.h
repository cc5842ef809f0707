#ifndef ssc_scenes_punch_scene_h
#define ssc_scenes_punch_scene_h

#include <deal.II/base/mpi.h>

#include <ssc/parameters.h>

#include <vector>

namespace ssc
{
  /**
   * Rigid flat cylindrical punch pressed to a prescribed depth at the patch
   * centre (displacement control, linear elasticity). The force is the
   * reaction of the punch dofs computed from the assembled residual.
   * Writes summary.json, force_displacement.csv, parameters.prm, log.txt and
   * the volume fields (volume.pvd) into output/<run name>/.
   */
  /// What the punch scene measured.
  struct PunchResult
  {
    types::global_dof_index dofs = 0;
    std::vector<double>     depths;
    std::vector<double>     forces;
    double                  stiffness            = 0;
    double                  half_space_stiffness = 0;
  };

  class PunchScene
  {
  public:
    PunchScene(const Parameters &parameters, const MPI_Comm mpi_communicator);

    PunchResult
    run();

    /// Half-space stiffness F/delta of a rigid flat punch of radius @p a on
    /// a material (E, nu): Sneddon (frictionless) or Mossakovskii/Spence
    /// (bonded, no slip).
    static double
    half_space_stiffness(const double       a,
                         const double       E,
                         const double       nu,
                         const PunchContact contact);

  private:
    const Parameters &parameters;
    MPI_Comm          mpi_communicator;
  };
} // namespace ssc

#endif
