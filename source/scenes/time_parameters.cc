#include <deal.II/base/exceptions.h>

#include <algorithm>
#include <cmath>

#include <ssc/scenes/time_parameters.h>

namespace ssc
{
  void
  TimeParameters::add_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Time");
    prm.add_parameter(
      "Loading history",
      history,
      "none: the scene's quasi-static path, no time (visco-elastic layers "
      "answer with their instantaneous moduli). ramp and hold (indentation "
      "only): the punch's load rises linearly over the Ramp time to its "
      "held value, the last of Punch/Forces under force control (creep: "
      "the depth grows) or Punch/Depth under displacement control "
      "(relaxation: the force falls), and is held for the Hold time.");
    prm.add_parameter("Ramp time",
                      ramp_time,
                      "Time (s) over which the load rises to its held value.",
                      Patterns::Double(0));
    prm.add_parameter("Hold time",
                      hold_time,
                      "Time (s) the load is held after the ramp.",
                      Patterns::Double(0));
    prm.add_parameter("Ramp steps",
                      ramp_steps,
                      "Number of equal time steps of the ramp.",
                      Patterns::Integer(1, 100000));
    prm.add_parameter("Hold steps",
                      hold_steps,
                      "Number of time steps of the hold.",
                      Patterns::Integer(1, 100000));
    prm.add_parameter(
      "Hold step growth",
      hold_step_growth,
      "Ratio of successive time steps of the hold (1: equal steps; > 1 "
      "puts short steps where the relaxation is fastest, at its start).",
      Patterns::Double(1, 10));
    prm.leave_subsection();
  }


  void
  TimeParameters::check() const
  {
    if (!enabled())
      return;
    AssertThrow(ramp_time > 0,
                ExcMessage("Time/Ramp time must be positive: a load applied "
                           "in no time has no rate."));
    AssertThrow(hold_time > 0,
                ExcMessage("Time/Hold time must be positive with Loading "
                           "history = ramp and hold."));
  }


  std::vector<double>
  TimeParameters::step_times() const
  {
    std::vector<double> times;
    for (unsigned int k = 1; k <= ramp_steps; ++k)
      times.push_back(ramp_time * k / ramp_steps);
    // steps h, h r, h r^2, ... summing to the hold time
    const double r = hold_step_growth;
    const double first =
      r == 1. ? hold_time / hold_steps :
                hold_time * (r - 1.) / (std::pow(r, hold_steps) - 1.);
    double step = first, t = ramp_time;
    for (unsigned int k = 1; k <= hold_steps; ++k, step *= r)
      {
        t += step;
        times.push_back(k == hold_steps ? ramp_time + hold_time : t);
      }
    return times;
  }


  double
  TimeParameters::load_fraction(const double t) const
  {
    return std::min(t / ramp_time, 1.);
  }
} // namespace ssc
