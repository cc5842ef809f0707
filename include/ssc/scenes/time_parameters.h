#ifndef ssc_scenes_time_parameters_h
#define ssc_scenes_time_parameters_h

#include <deal.II/base/parameter_handler.h>

#include <array>
#include <utility>
#include <vector>

#include <ssc/base/enum_table.h>

namespace ssc
{
  using namespace dealii;

  /// The loading in time of a scene.
  enum class LoadingHistory
  {
    /// no time: the quasi-static path through the loads, laws answer
    /// instantly
    none,
    /// the load rises linearly to its held value, then is held
    ramp_and_hold
  };

  constexpr std::array<std::pair<LoadingHistory, const char *>, 2>
  enum_table(LoadingHistory)
  {
    return {{{LoadingHistory::none, "none"},
             {LoadingHistory::ramp_and_hold, "ramp and hold"}}};
  }

  /**
   * Section "Time": the loading history of a time-dependent indentation
   * (creep under a held force, relaxation at a held depth), and its time
   * steps. The steps are fixed: the ramp's are equal, the hold's grow
   * geometrically (relaxation is fastest at its start); the error they
   * leave is shown by halving them (the integration of the visco-elastic
   * laws is second order in the step).
   */
  struct TimeParameters
  {
    LoadingHistory history    = LoadingHistory::none;
    double         ramp_time  = 1;
    double         hold_time  = 600;
    unsigned int   ramp_steps = 4;
    unsigned int   hold_steps = 24;
    /// Ratio of successive hold steps (1: equal steps).
    double hold_step_growth = 1.2;

    bool
    enabled() const
    {
      return history != LoadingHistory::none;
    }

    void
    add_parameters(ParameterHandler &prm);

    /// Throws, naming the entry, on inconsistent values.
    void
    check() const;

    /// The end times of the steps (s), increasing, the last one the end of
    /// the hold.
    std::vector<double>
    step_times() const;

    /// The fraction of the held load applied at time @p t: t / ramp time
    /// on the ramp, 1 after it.
    double
    load_fraction(const double t) const;
  };
} // namespace ssc

#endif
