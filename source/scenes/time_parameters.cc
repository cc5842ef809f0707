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
      "answer with their instantaneous moduli). The others (indentation "
      "only) move the punch's load in time; its peak is the last of "
      "Punch/Forces under force control (creep: the depth follows) or "
      "Punch/Depth under displacement control (relaxation: the force "
      "follows). ramp and hold: the load rises linearly over the Ramp "
      "time and is held for the Hold time. ramp, hold and unload: then "
      "falls linearly to zero over the Unload time, and the body recovers "
      "for the Recovery time. cyclic: Cycles triangles from zero to the "
      "peak and back, each over the Cycle period.");
    prm.add_parameter("Ramp time",
                      ramp_time,
                      "Time (s) over which the load rises to its peak.",
                      Patterns::Double(0));
    prm.add_parameter("Hold time",
                      hold_time,
                      "Time (s) the peak load is held after the ramp.",
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
      "Ratio of successive time steps of the hold and of the recovery (1: "
      "equal steps; > 1 puts short steps where the relaxation is fastest, "
      "at their start).",
      Patterns::Double(1, 10));
    prm.add_parameter("Unload time",
                      unload_time,
                      "Time (s) over which the load falls from its peak to "
                      "zero (ramp, hold and unload).",
                      Patterns::Double(0));
    prm.add_parameter("Unload steps",
                      unload_steps,
                      "Number of equal time steps of the unloading.",
                      Patterns::Integer(1, 100000));
    prm.add_parameter("Recovery time",
                      recovery_time,
                      "Time (s) the body recovers at zero load after the "
                      "unloading (0: none).",
                      Patterns::Double(0));
    prm.add_parameter("Recovery steps",
                      recovery_steps,
                      "Number of time steps of the recovery.",
                      Patterns::Integer(1, 100000));
    prm.add_parameter("Cycles",
                      cycles,
                      "Number of load cycles (cyclic).",
                      Patterns::Integer(1, 10000));
    prm.add_parameter("Cycle period",
                      cycle_period,
                      "Duration (s) of one cycle, zero to peak and back "
                      "(cyclic).",
                      Patterns::Double(0));
    prm.add_parameter("Steps per cycle",
                      steps_per_cycle,
                      "Number of equal time steps of one cycle, half of "
                      "them rising (cyclic; even).",
                      Patterns::Integer(2, 100000));
    prm.leave_subsection();
  }


  void
  TimeParameters::check() const
  {
    if (holds())
      {
        AssertThrow(ramp_time > 0,
                    ExcMessage("Time/Ramp time must be positive: a load "
                               "applied in no time has no rate."));
        AssertThrow(hold_time > 0,
                    ExcMessage("Time/Hold time must be positive with "
                               "Loading history = " +
                               std::string(to_string(history)) + "."));
      }
    if (history == LoadingHistory::ramp_hold_and_unload)
      AssertThrow(unload_time > 0,
                  ExcMessage("Time/Unload time must be positive: a load "
                             "removed in no time has no rate."));
    if (history == LoadingHistory::cyclic)
      {
        AssertThrow(cycle_period > 0,
                    ExcMessage("Time/Cycle period must be positive with "
                               "Loading history = cyclic."));
        AssertThrow(steps_per_cycle % 2 == 0,
                    ExcMessage("Time/Steps per cycle must be even: half of "
                               "them rise to the peak, half fall back."));
      }
  }


  std::vector<TimeParameters::Segment>
  TimeParameters::segments() const
  {
    std::vector<Segment> pieces;
    switch (history)
      {
        case LoadingHistory::none:
          break;
        case LoadingHistory::cyclic:
          for (unsigned int c = 0; c < cycles; ++c)
            {
              pieces.push_back({cycle_period / 2, 1., steps_per_cycle / 2, 1.});
              pieces.push_back({cycle_period / 2, 0., steps_per_cycle / 2, 1.});
            }
          break;
        case LoadingHistory::ramp_and_hold:
        case LoadingHistory::ramp_hold_and_unload:
          pieces.push_back({ramp_time, 1., ramp_steps, 1.});
          pieces.push_back({hold_time, 1., hold_steps, hold_step_growth});
          if (history == LoadingHistory::ramp_hold_and_unload)
            {
              pieces.push_back({unload_time, 0., unload_steps, 1.});
              if (recovery_time > 0)
                pieces.push_back(
                  {recovery_time, 0., recovery_steps, hold_step_growth});
            }
          break;
      }
    return pieces;
  }


  std::vector<double>
  TimeParameters::step_times() const
  {
    std::vector<double> times;
    double              start = 0;
    for (const Segment &segment : segments())
      {
        // steps h, h r, h r^2, ... summing to the segment's duration
        const double r    = segment.step_growth;
        const double n    = segment.steps;
        double       step = r == 1. ?
                              segment.duration / n :
                              segment.duration * (r - 1.) / (std::pow(r, n) - 1.);
        double       t    = start;
        for (unsigned int k = 1; k <= segment.steps; ++k, step *= r)
          {
            t = r == 1. ? start + segment.duration * k / n : t + step;
            times.push_back(k == segment.steps ? start + segment.duration : t);
          }
        start += segment.duration;
      }
    return times;
  }


  unsigned int
  TimeParameters::steps_through_segment(const unsigned int k) const
  {
    const std::vector<Segment> pieces = segments();
    AssertIndexRange(k, pieces.size());
    unsigned int steps = 0;
    for (unsigned int i = 0; i <= k; ++i)
      steps += pieces[i].steps;
    return steps;
  }


  double
  TimeParameters::load_fraction(const double t) const
  {
    double start = 0, fraction = 0;
    for (const Segment &segment : segments())
      {
        if (t <= start + segment.duration)
          return fraction + (segment.end_fraction - fraction) *
                              std::max(t - start, 0.) / segment.duration;
        start += segment.duration;
        fraction = segment.end_fraction;
      }
    return fraction;
  }
} // namespace ssc
