#ifndef ssc_scenes_punch_loading_h
#define ssc_scenes_punch_loading_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>

#include <functional>
#include <memory>

#include <ssc/contact/punch_friction.h>
#include <ssc/contact/rigid_punch_contact.h>
#include <ssc/mechanics/elastic_system.h>
#include <ssc/scenes/parameters.h>

namespace ssc
{
  class QuasiStaticDriver;

  /**
   * The rigid flat cylindrical punch of the indentation scene as boundary
   * conditions of the elastic system: the patch's supports, u_x = u_y = 0
   * under the punch if it is bonded, and u_z = -depth (displacement
   * control) or u_z tied to one master dof that carries the force (force
   * control); Coulomb friction on the face if asked for; optionally the
   * skin's contact with the punch's rounded edge.
   * The load parameter is the depth (mm) or the force (N).
   */
  class PunchLoading
  {
  public:
    /// Sets up the system's constraints (after its dofs are distributed).
    PunchLoading(const Parameters   &parameters,
                 ElasticSystem      &system,
                 TimerOutput        &timer,
                 ConditionalOStream &pcout);

    /// Applies the load @p load (depth or force).
    void
    apply(const double load);

    /// The force on the punch (N) at the current state: the prescribed one
    /// under force control, the reaction under displacement control.
    double
    force(const double load);

    /// The reaction of the punch's condition (the tie's under force
    /// control, which balances the applied force), N.
    double
    reaction_force();

    /// The punch's depth (mm) at the current state.
    double
    depth(const double load) const;

    /// The edge contact (null without it).
    const RigidPunchContact *
    edge_contact() const
    {
      return contact.get();
    }

    /// The friction on the face (null unless Contact = friction).
    PunchFriction *
    friction()
    {
      return face_friction.get();
    }

    bool
    force_control() const
    {
      return by_force;
    }

  private:
    ElasticSystem &system;
    const bool     by_force;
    /// The whole patch's forces over the model's (4 for a quarter).
    const double                       symmetry_factor;
    unsigned int                       punch_condition = 0;
    std::unique_ptr<RigidPunchContact> contact;
    std::unique_ptr<PunchFriction>     face_friction;
  };


  /**
   * Brings @p driver through the punch's loads of @p parameters (the Forces,
   * or the equal depth steps) applied by @p loading, Newton's first
   * increment the first load over Nonlinear solver/Initial steps, calling
   * @p on_step(k) after load k: the path of an indentation run, in one
   * place so that the scene and its error estimate's second discretisation
   * take the same one.
   */
  void
  follow_punch_path(QuasiStaticDriver                       &driver,
                    PunchLoading                            &loading,
                    const Parameters                        &parameters,
                    const std::function<void(unsigned int)> &on_step);
} // namespace ssc

#endif
