#ifndef ssc_scenes_punch_parameters_h
#define ssc_scenes_punch_parameters_h

#include <deal.II/base/parameter_handler.h>

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

  /// A rigid flat cylindrical punch at the patch centre, pressed to a depth.
  struct PunchParameters
  {
    double       radius     = 2.5;
    double       depth      = 0.5;
    PunchContact contact    = PunchContact::bonded;
    unsigned int load_steps = 1;

    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm);
  };
} // namespace ssc

#endif
