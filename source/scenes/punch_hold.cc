#include <iomanip>

#include <ssc/scenes/punch_hold.h>
#include <ssc/scenes/quasi_static_driver.h>

namespace ssc
{
  PunchHold::PunchHold(const Parameters &parameters)
    : parameters(parameters)
    , step_times(parameters.time.step_times())
    , peak_load(parameters.punch.loads().back())
  {
    for (const double t : step_times)
      step_loads.push_back(peak_load * parameters.time.load_fraction(t));
    if (parameters.time.holds())
      {
        ramp_end = parameters.time.steps_through_segment(0) - 1;
        hold_end = parameters.time.steps_through_segment(1) - 1;
      }
  }


  void
  PunchHold::follow(QuasiStaticDriver                       &driver,
                    PunchLoading                            &loading,
                    ElasticSystem                           &system,
                    const std::function<void(unsigned int)> &on_step) const
  {
    driver.run(
      step_times,
      [&](const double t) {
        loading.apply(peak_load * parameters.time.load_fraction(t));
        system.set_time(t);
      },
      // the first step split as the quasi-static path splits its first
      // load
      step_times.front() / parameters.newton.initial_steps,
      // the relaxation over the step changes the tangent with it
      LoadDependence::tangent,
      on_step);
  }


  double
  PunchHold::relaxed_fraction(const IndentationResult &result) const
  {
    AssertThrow(parameters.time.holds(), ExcInternalError());
    if (parameters.punch.control == PunchControl::force)
      return 1. - result.depths[ramp_end] / result.depths[hold_end];
    return 1. - result.forces[hold_end] / result.forces[ramp_end];
  }


  double
  PunchHold::residual_fraction(const IndentationResult &result) const
  {
    AssertThrow(parameters.time.history == LoadingHistory::ramp_hold_and_unload,
                ExcInternalError());
    if (parameters.punch.control == PunchControl::force)
      return result.depths.back() / result.depths[hold_end];
    return result.forces.back() / result.forces[hold_end];
  }


  std::vector<double>
  PunchHold::hysteresis_per_cycle(const IndentationResult &result) const
  {
    AssertThrow(parameters.time.history == LoadingHistory::cyclic,
                ExcInternalError());
    const unsigned int  steps = parameters.time.steps_per_cycle;
    std::vector<double> work;
    for (unsigned int c = 0; c < parameters.time.cycles; ++c)
      {
        double area = 0;
        for (unsigned int k = c * steps; k < (c + 1) * steps; ++k)
          {
            // the unloaded start before the first step
            const double force_before = k == 0 ? 0. : result.forces[k - 1];
            const double depth_before = k == 0 ? 0. : result.depths[k - 1];
            area += 0.5 * (force_before + result.forces[k]) *
                    (result.depths[k] - depth_before);
          }
        work.push_back(area);
      }
    return work;
  }


  void
  PunchHold::record(const IndentationResult &result,
                    nlohmann::ordered_json  &summary,
                    const RunOutput         &output) const
  {
    const TimeParameters &time = parameters.time;
    const bool by_force = parameters.punch.control == PunchControl::force;
    summary["time_s"]   = step_times;
    summary["depth_mm_vs_time"] = result.depths;
    summary["force_N_vs_time"]  = result.forces;
    summary["relaxed_fraction"] =
      time.holds() ? nlohmann::ordered_json(relaxed_fraction(result)) :
                     nlohmann::ordered_json();
    summary["residual_fraction"] =
      time.history == LoadingHistory::ramp_hold_and_unload ?
        nlohmann::ordered_json(residual_fraction(result)) :
        nlohmann::ordered_json();
    summary["hysteresis_mJ"] =
      time.history == LoadingHistory::cyclic ?
        nlohmann::ordered_json(hysteresis_per_cycle(result)) :
        nlohmann::ordered_json();
    nlohmann::ordered_json history = {
      {"history", to_string(time.history)},
      {"kind", by_force ? "creep" : "relaxation"},
      {"peak_load", peak_load},
      {"peak_load_unit", by_force ? "N" : "mm"}};
    if (time.holds())
      {
        history["ramp_end_s"] = step_times[ramp_end];
        history["hold_end_s"] = step_times[hold_end];
      }
    if (time.history == LoadingHistory::cyclic)
      {
        history["cycle_period_s"] = time.cycle_period;
        history["cycles"]         = time.cycles;
      }
    history["steps"]           = step_times.size();
    summary["loading_history"] = history;
    output.write_file("time_history.csv", [&](std::ostream &out) {
      out << "time_s,force_N,depth_mm\n" << std::setprecision(10);
      for (unsigned int k = 0; k < step_times.size(); ++k)
        out << step_times[k] << ',' << result.forces[k] << ','
            << result.depths[k] << '\n';
    });
  }


  void
  PunchHold::print(const IndentationResult &result,
                   ConditionalOStream      &out) const
  {
    const TimeParameters &time = parameters.time;
    out << std::setprecision(4);
    if (time.holds())
      out << "Relaxed fraction over the hold: " << relaxed_fraction(result)
          << std::endl;
    if (time.history == LoadingHistory::ramp_hold_and_unload)
      out << "Residual fraction after the recovery: "
          << residual_fraction(result) << std::endl;
    if (time.history == LoadingHistory::cyclic)
      {
        out << "Work per cycle (mJ, the force-depth loop's area):";
        for (const double work : hysteresis_per_cycle(result))
          out << ' ' << work;
        out << std::endl;
      }
  }
} // namespace ssc
