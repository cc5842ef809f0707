#ifndef ssc_scenes_indentation_scene_h
#define ssc_scenes_indentation_scene_h

#include <deal.II/base/mpi.h>

#include <vector>

#include <ssc/scenes/indentation_record.h>
#include <ssc/scenes/parameters.h>
#include <ssc/scenes/scene.h>

namespace ssc
{
  /**
   * A rigid flat punch (cylindrical or rectangular) at the patch centre,
   * bonded or frictionless, under displacement control (the depths are
   * prescribed, the force is the reaction computed from the assembled residual)
   * or force control (the forces are prescribed, the vertical displacements
   * under the punch are tied to one master unknown whose value is the
   * depth). Small-strain elasticity is linear, so one solve for a unit load
   * gives every load step by scaling.
   *
   * Writes into output/<run name>/: summary.json, force_displacement.csv,
   * surface_profile.csv (u_z along y = 0 per step), section.csv (the plane
   * y = 0 at the last step), volume.pvd, septa.pvd and ligaments.pvd when
   * the microstructure is on, parameters.prm, log.txt.
   */
  class IndentationScene : public Scene
  {
  public:
    using Scene::Scene;

    IndentationResult
    run();

    /// Half-space stiffness F/delta of a rigid flat punch of radius @p a on
    /// a material (E, nu): Sneddon (frictionless) or Mossakovskii/Spence
    /// (bonded, no slip; also for a punch with friction, whose stiffness
    /// lies between the two).
    static double
    half_space_stiffness(const double       a,
                         const double       E,
                         const double       nu,
                         const PunchContact contact);
  };
} // namespace ssc

#endif
