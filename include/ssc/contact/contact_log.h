#ifndef ssc_contact_contact_log_h
#define ssc_contact_contact_log_h

#include <deal.II/lac/trilinos_vector.h>

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

#include <ssc/contact/punch_friction.h>
#include <ssc/contact/rigid_punch_contact.h>

namespace ssc
{
  /**
   * What the skin's contact with the punch's rounded edge did at each load
   * step (contact area, largest penetration), and the "edge_contact"
   * section of summary.json made from it: the contact writes its own
   * record, so a scene only says when a step is done.
   */
  class EdgeContactLog
  {
  public:
    /// Records the state at the converged solution @p u (collective) and
    /// returns the step's progress line.
    std::string
    record(const RigidPunchContact             &contact,
           const TrilinosWrappers::MPI::Vector &u);

    /// The summary section, with the edge radius (mm) and penalty factor
    /// the contact was made with.
    nlohmann::ordered_json
    summary(const double edge_radius, const double penalty_factor) const;

  private:
    std::vector<double> areas;
    std::vector<double> penetrations;
  };


  /**
   * What Coulomb friction under the punch did at each load step (nodes
   * sticking and slipping, the normal force the step was solved with), and
   * the "friction" section of summary.json.
   */
  class FrictionLog
  {
  public:
    /// Records the last accepted state of @p friction; @p symmetry_factor
    /// turns the model's normal force into the whole punch's (4 on a
    /// quarter). Returns the step's progress line.
    std::string
    record(const PunchFriction &friction, const double symmetry_factor);

    /// The summary section, with the friction coefficient and penalty
    /// factor and the number of nodes under the face (collective).
    nlohmann::ordered_json
    summary(const PunchFriction &friction,
            const double         coefficient,
            const double         penalty_factor) const;

  private:
    std::vector<unsigned int> sticking;
    std::vector<unsigned int> slipping;
    std::vector<double>       normal_forces;
  };
} // namespace ssc

#endif
