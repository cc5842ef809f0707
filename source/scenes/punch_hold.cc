#include <iomanip>

#include <ssc/scenes/punch_hold.h>
#include <ssc/scenes/quasi_static_driver.h>

namespace ssc
{
  PunchHold::PunchHold(const Parameters &parameters)
    : parameters(parameters)
    , step_times(parameters.time.step_times())
    , held_load(parameters.punch.loads().back())
    , ramp_end(parameters.time.ramp_steps - 1)
  {
    for (const double t : step_times)
      step_loads.push_back(held_load * parameters.time.load_fraction(t));
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
        loading.apply(held_load * parameters.time.load_fraction(t));
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
    if (parameters.punch.control == PunchControl::force)
      return 1. - result.depths[ramp_end] / result.depths.back();
    return 1. - result.forces.back() / result.forces[ramp_end];
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
    summary["relaxed_fraction"] = relaxed_fraction(result);
    summary["loading_history"]  = {{"history", to_string(time.history)},
                                   {"kind", by_force ? "creep" : "relaxation"},
                                   {"held_load", held_load},
                                   {"held_load_unit", by_force ? "N" : "mm"},
                                   {"ramp_time_s", time.ramp_time},
                                   {"hold_time_s", time.hold_time},
                                   {"ramp_steps", time.ramp_steps},
                                   {"hold_steps", time.hold_steps},
                                   {"hold_step_growth", time.hold_step_growth}};
    output.write_file("time_history.csv", [&](std::ostream &out) {
      out << "time_s,force_N,depth_mm\n" << std::setprecision(10);
      for (unsigned int k = 0; k < step_times.size(); ++k)
        out << step_times[k] << ',' << result.forces[k] << ','
            << result.depths[k] << '\n';
    });
  }
} // namespace ssc
