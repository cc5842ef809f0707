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
    /// the load rises linearly to its peak, then is held
    ramp_and_hold,
    /// ramp and hold, then the load falls linearly to zero and the body
    /// recovers (creep recovery, or the force after a held depth)
    ramp_hold_and_unload,
    /// triangular cycles between zero and the peak load (hysteresis)
    cyclic
  };

  constexpr std::array<std::pair<LoadingHistory, const char *>, 4>
  enum_table(LoadingHistory)
  {
    return {{{LoadingHistory::none, "none"},
             {LoadingHistory::ramp_and_hold, "ramp and hold"},
             {LoadingHistory::ramp_hold_and_unload, "ramp, hold and unload"},
             {LoadingHistory::cyclic, "cyclic"}}};
  }

  /**
   * Section "Time": the loading history of a time-dependent indentation
   * (creep under a held force, relaxation at a held depth, their recovery
   * after unloading, cycles), and its time steps. The history is a
   * piecewise linear load fraction (of the peak load) through segments;
   * the steps are fixed per segment: equal where the load changes,
   * growing geometrically where it is held (relaxation is fastest at the
   * start of a hold). The error they leave is shown by halving them (the
   * integration of the visco-elastic laws is second order in the step).
   */
  struct TimeParameters
  {
    LoadingHistory history    = LoadingHistory::none;
    double         ramp_time  = 1;
    double         hold_time  = 600;
    unsigned int   ramp_steps = 4;
    unsigned int   hold_steps = 24;
    /// Ratio of successive steps of a hold or recovery (1: equal steps).
    double       hold_step_growth = 1.2;
    double       unload_time      = 1;
    unsigned int unload_steps     = 4;
    double       recovery_time    = 600;
    unsigned int recovery_steps   = 24;
    unsigned int cycles           = 3;
    double       cycle_period     = 2;
    unsigned int steps_per_cycle  = 16;

    /// One piece of the history: over @p duration the load fraction goes
    /// linearly from the previous segment's end to @p end_fraction, in
    /// @p steps steps growing by @p step_growth.
    struct Segment
    {
      double       duration;
      double       end_fraction;
      unsigned int steps;
      double       step_growth;
    };

    bool
    enabled() const
    {
      return history != LoadingHistory::none;
    }

    /// Whether the history holds its peak load (ramp and hold, with or
    /// without unloading): the relaxed fraction is defined.
    bool
    holds() const
    {
      return history == LoadingHistory::ramp_and_hold ||
             history == LoadingHistory::ramp_hold_and_unload;
    }

    void
    add_parameters(ParameterHandler &prm);

    /// Throws, naming the entry, on inconsistent values.
    void
    check() const;

    /// The history's segments, from the unloaded state at t = 0.
    std::vector<Segment>
    segments() const;

    /// The end times of the steps (s), increasing, the last one the end of
    /// the history.
    std::vector<double>
    step_times() const;

    /// The number of steps from the start to the end of segment @p k.
    unsigned int
    steps_through_segment(const unsigned int k) const;

    /// The fraction of the peak load applied at time @p t (linear within
    /// each segment; the last segment's end fraction after it).
    double
    load_fraction(const double t) const;
  };
} // namespace ssc

#endif
