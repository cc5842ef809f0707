#ifndef ssc_scenes_punch_hold_h
#define ssc_scenes_punch_hold_h

#include <nlohmann/json.hpp>

#include <functional>
#include <vector>

#include <ssc/output/run_output.h>
#include <ssc/scenes/indentation_record.h>
#include <ssc/scenes/parameters.h>
#include <ssc/scenes/punch_loading.h>

namespace ssc
{
  /**
   * The indentation in time (Time/Loading history): the punch's load moved
   * through the history of TimeParameters, creep under a held force and
   * relaxation at a held depth, their recovery after unloading, cycles.
   * The load parameter of the path is the time; each step sets the load
   * and the time of the state it solves (ElasticSystem::set_time()), over
   * which the visco-elastic layers relax.
   */
  class PunchHold
  {
  public:
    explicit PunchHold(const Parameters &parameters);

    /// The end times of the steps (s).
    const std::vector<double> &
    times() const
    {
      return step_times;
    }

    /// The punch's load (force or depth) at the end of each step.
    const std::vector<double> &
    loads() const
    {
      return step_loads;
    }

    /// Brings @p driver through the steps, the punch's load applied by
    /// @p loading, calling @p on_step(k) after step k.
    void
    follow(QuasiStaticDriver                       &driver,
           PunchLoading                            &loading,
           ElasticSystem                           &system,
           const std::function<void(unsigned int)> &on_step) const;

    /// The fraction of the response that came with time over the hold:
    /// under force control 1 - (depth at the end of the ramp) / (depth at
    /// the end of the hold), under displacement control 1 - (force at the
    /// end of the hold) / (force at the end of the ramp). For one Prony
    /// term on a homogeneous incompressible body loaded fast, both tend to
    /// its relative modulus. Needs a history that holds.
    double
    relaxed_fraction(const IndentationResult &result) const;

    /// After unloading and recovery, what is left of the response at the
    /// end of the hold: the depth (creep) or the force (relaxation; the
    /// bonded punch back at zero depth holds the relaxed tissue, so the
    /// force is a pull, negative) at the end over that at the end of the
    /// hold.
    double
    residual_fraction(const IndentationResult &result) const;

    /// The energy each load cycle dissipates, the area of its force-depth
    /// loop (mJ = N mm; trapezoidal rule over the steps), cyclic only.
    std::vector<double>
    hysteresis_per_cycle(const IndentationResult &result) const;

    /// summary.json's time keys (time_s, depth_mm_vs_time, force_N_vs_time,
    /// relaxed_fraction, residual_fraction, hysteresis_mJ, loading_history;
    /// null where the history does not define them) and
    /// time_history.csv.
    void
    record(const IndentationResult &result,
           nlohmann::ordered_json  &summary,
           const RunOutput         &output) const;

    /// The history's measures on @p out (rank 0), one line each.
    void
    print(const IndentationResult &result, ConditionalOStream &out) const;

  private:
    const Parameters   &parameters;
    std::vector<double> step_times;
    std::vector<double> step_loads;
    /// The peak load: the last force (creep) or the depth (relaxation).
    const double peak_load;
    /// The indices of the steps that end the ramp and the hold (holding
    /// histories).
    unsigned int ramp_end = 0, hold_end = 0;
  };
} // namespace ssc

#endif
