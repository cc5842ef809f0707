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
   * The indentation in time (Time/Loading history = ramp and hold): the
   * punch's load ramped to its held value and held, creep under a held
   * force, relaxation at a held depth. The load parameter of the path is
   * the time; each step sets the load and the time of the state it solves
   * (ElasticSystem::set_time()), over which the visco-elastic layers relax.
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

    /// The fraction of the response that came with time: under force
    /// control 1 - (depth at the end of the ramp) / (depth at the end),
    /// under displacement control 1 - (force at the end) / (force at the
    /// end of the ramp). For one Prony term on a homogeneous
    /// incompressible body loaded fast, both tend to its relative modulus.
    double
    relaxed_fraction(const IndentationResult &result) const;

    /// summary.json's time keys (time_s, depth_mm_vs_time, force_N_vs_time,
    /// relaxed_fraction, loading_history) and time_history.csv.
    void
    record(const IndentationResult &result,
           nlohmann::ordered_json  &summary,
           const RunOutput         &output) const;

  private:
    const Parameters   &parameters;
    std::vector<double> step_times;
    std::vector<double> step_loads;
    /// The held load: the last force (creep) or the depth (relaxation).
    const double held_load;
    /// The index of the step that ends the ramp.
    unsigned int ramp_end;
  };
} // namespace ssc

#endif
