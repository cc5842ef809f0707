#ifndef ssc_scenes_punch_parameters_h
#define ssc_scenes_punch_parameters_h

#include <deal.II/base/parameter_handler.h>

#include <vector>

namespace ssc
{
  using namespace dealii;

  /// Bonded: the punch holds all displacement components of the skin under
  /// it; frictionless: only the vertical one (Sneddon's problem).
  enum class PunchContact
  {
    bonded,
    frictionless
  };

  /// Whether the punch's depth or its force is prescribed.
  enum class PunchControl
  {
    displacement,
    force
  };

  /// A rigid flat cylindrical punch at the patch centre (section "Punch").
  struct PunchParameters
  {
    double              radius         = 2.5;
    PunchContact        contact        = PunchContact::bonded;
    PunchControl        control        = PunchControl::displacement;
    double              depth          = 0.5;
    unsigned int        load_steps     = 1;
    std::vector<double> forces         = {0.35, 0.5, 0.75, 1.0, 1.25, 1.5, 1.8};
    double              profile_length = 30;
    unsigned int        profile_points = 301;
    bool                section        = true;
    bool                edge_contact   = false;
    double              edge_radius    = 0.5;
    double              contact_penalty = 100;

    /// The loads of the steps: depths (mm) or forces (N).
    std::vector<double>
    loads() const;

    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm);
  };
} // namespace ssc

#endif
