#include <sstream>

#include <ssc/contact/contact_log.h>

namespace ssc
{
  std::string
  EdgeContactLog::record(const RigidPunchContact             &contact,
                         const TrilinosWrappers::MPI::Vector &u)
  {
    const auto [area, penetration] = contact.contact_state(u);
    areas.push_back(area);
    penetrations.push_back(penetration);
    std::ostringstream line;
    line << "  edge contact: " << area << " mm^2 of skin, largest penetration "
         << penetration << " mm";
    return line.str();
  }


  nlohmann::ordered_json
  EdgeContactLog::summary(const double edge_radius,
                          const double penalty_factor) const
  {
    return {{"edge_radius_mm", edge_radius},
            {"penalty_factor", penalty_factor},
            {"area_mm2_per_step", areas},
            {"max_penetration_mm_per_step", penetrations}};
  }


  std::string
  FrictionLog::record(const PunchFriction &friction,
                      const double         symmetry_factor)
  {
    const FrictionState &state = friction.accepted_state();
    sticking.push_back(state.sticking);
    slipping.push_back(state.slipping);
    // the whole punch's, as the force
    normal_forces.push_back(state.normal_force * symmetry_factor);
    std::ostringstream line;
    line << "  friction: " << state.sticking << " nodes stick, "
         << state.slipping << " slip, " << state.free << " not pressed";
    return line.str();
  }


  nlohmann::ordered_json
  FrictionLog::summary(const PunchFriction &friction,
                       const double         coefficient,
                       const double         penalty_factor) const
  {
    return {{"coefficient", coefficient},
            {"penalty_factor", penalty_factor},
            {"nodes", friction.n_nodes()},
            {"sticking_nodes_per_step", sticking},
            {"slipping_nodes_per_step", slipping},
            {"normal_force_N_per_step", normal_forces},
            {"note",
             "normal forces: the tie's reactions the last solve of the step "
             "used, settled to 2 % (staggered)"}};
  }
} // namespace ssc
