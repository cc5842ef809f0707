#include <deal.II/base/exceptions.h>

#include <cmath>
#include <iomanip>

#include <ssc/scenes/wound_record.h>

namespace ssc
{
  WoundRecord::WoundRecord(const Parameters   &parameters,
                           const double        langer_line_angle,
                           ConditionalOStream &pcout)
    : parameters(parameters)
    , langer(langer_line_angle)
    , pcout(pcout)
  {
    wound_table << "cut,step,prestretch_fraction,gap_mm,area_mm2,length_mm,"
                   "aspect_ratio,orientation_deg\n";
    closure_table << "cut,step,closure_fraction,force_per_suture_N,"
                     "max_suture_force_N,max_skin_stress_kPa,"
                     "dog_ear_height_mm,residual_gap_mm\n";
    if (!std::isnan(langer) &&
        parameters.incision.shape != Incision::Shape::disc)
      {
        const double difference = std::abs(std::remainder(langer, 90.));
        AssertThrow(difference < 1e-6,
                    ExcMessage("The incision scene cuts along x and y, along "
                               "and across Langer's lines; the skin's Langer "
                               "line angle at the patch centre is " +
                               std::to_string(langer) +
                               " degrees: give 0 or 90 (the direction of the "
                               "lines relative to the cut is what matters)."));
      }
  }


  std::string
  WoundRecord::relation(const unsigned int direction) const
  {
    if (std::isnan(langer) || incision.shape == Incision::Shape::disc)
      return "";
    const double difference =
      std::abs(std::remainder(90. * direction - langer, 180.));
    return difference < 45. ? "along" : "across";
  }


  void
  WoundRecord::begin_model(const Incision &model_incision)
  {
    incision                  = model_incision;
    const char       *axis[2] = {"x", "y"};
    const std::string where   = relation(incision.direction);
    switch (incision.shape)
      {
        case Incision::Shape::line:
          name = axis[incision.direction];
          key  = "cut_along_" + name;
          pcout << "Incision along " << name << " (" << incision.length
                << " mm";
          break;
        case Incision::Shape::disc:
          name = "disc";
          key  = "excision";
          pcout << "Excision of a disc (" << incision.length << " mm across";
          break;
        case Incision::Shape::ellipse:
          name = axis[incision.direction];
          key  = "ellipse_along_" + name;
          pcout << "Excision of an ellipse along " << name << " ("
                << incision.length << " by " << incision.width << " mm";
          break;
      }
    pcout << " through " << incision.n_cut_layers << " layer(s)"
          << (where.empty() ? "" : ", " + where + " Langer's lines") << ")"
          << std::endl;
  }


  void
  WoundRecord::record_wound(const unsigned int step,
                            const double       fraction,
                            const WoundShape  &measured)
  {
    wound = measured;
    pcout << "  pre-tension " << std::setprecision(4) << 100 * fraction
          << " %: gap " << wound.gap_mm << " mm, area " << wound.area_mm2
          << " mm^2, length " << wound.length_mm << " mm";
    if (incision.excision())
      pcout << ", area change " << wound.area_change_pct << " %, aspect ratio "
            << wound.aspect_ratio;
    pcout << std::endl;
    wound_table << name << ',' << step << ',' << fraction << ',' << wound.gap_mm
                << ',' << wound.area_mm2 << ',' << wound.length_mm << ','
                << wound.aspect_ratio << ',' << wound.orientation_deg << '\n';
  }


  void
  WoundRecord::record_closure(const unsigned int  step,
                              const ClosureState &state)
  {
    closure = state;
    pcout << "  closure " << std::setprecision(4) << 100 * state.fraction
          << " %: " << state.mean_force_N() << " N per suture (largest "
          << state.max_force_N() << "), skin stress up to "
          << state.max_skin_stress_kPa << " kPa, dog ears "
          << state.dog_ear_height_mm << " mm" << std::endl;
    closure_table << name << ',' << step << ',' << state.fraction << ','
                  << state.mean_force_N() << ',' << state.max_force_N() << ','
                  << state.max_skin_stress_kPa << ',' << state.dog_ear_height_mm
                  << ',' << state.residual_gap_mm << '\n';
  }


  void
  WoundRecord::end_model(const nlohmann::ordered_json &solver,
                         const nlohmann::ordered_json &closure_solver)
  {
    std::istringstream rows(wound.lips_csv());
    std::string        row;
    std::getline(rows, row);
    if (final_wounds.empty())
      lips_table << "cut," << row << '\n';
    while (std::getline(rows, row))
      lips_table << name << ',' << row << '\n';

    const std::string      where = relation(incision.direction);
    nlohmann::ordered_json entry = wound.to_json();
    entry["relative_to_langer_lines"] =
      where.empty() ? nlohmann::ordered_json() : nlohmann::ordered_json(where);
    wound_entries[key] = entry;
    solvers[key]       = solver;
    final_wounds.push_back(wound);
    if (!closure_solver.is_null())
      {
        nlohmann::ordered_json closed      = closure.to_json();
        closed["relative_to_langer_lines"] = entry["relative_to_langer_lines"];
        closure_entries[key]               = closed;
        solvers[key + "_closure"]          = closure_solver;
        final_closures.push_back(closure);
      }
  }


  void
  WoundRecord::write_tables(RunOutput &output) const
  {
    output.write_text("wound.csv", wound_table.str());
    output.write_text("wound_lips.csv", lips_table.str());
    if (!final_closures.empty())
      output.write_text("closure.csv", closure_table.str());
  }


  void
  WoundRecord::add_ratio(nlohmann::ordered_json    &json,
                         const std::string         &quantity,
                         const std::vector<double> &values) const
  {
    if (values.size() != 2)
      return;
    if (std::isnan(langer))
      {
        json[quantity + "_ratio_x_to_y"] = values[0] / values[1];
        pcout << "Ratio of the " << quantity
              << "s, x to y: " << values[0] / values[1] << std::endl;
      }
    else
      {
        const unsigned int across = relation(0) == "across" ? 0 : 1;
        json[quantity + "_ratio_across_to_along"] =
          values[across] / values[1 - across];
        pcout << "Ratio of the " << quantity
              << "s, across to along Langer's lines: "
              << values[across] / values[1 - across] << std::endl;
      }
  }


  void
  WoundRecord::add_to_summary(nlohmann::ordered_json      &summary,
                              const std::array<double, 2> &tension) const
  {
    // the interface's totals over every model and phase, and each one's
    // own record
    nlohmann::ordered_json totals = {{"linear_iterations", 0},
                                     {"newton_iterations", 0}};
    for (const auto &record : solvers)
      for (const char *total : {"linear_iterations", "newton_iterations"})
        totals[total] =
          totals[total].get<unsigned int>() + record[total].get<unsigned int>();
    totals["preconditioner"] = solvers.begin().value()["preconditioner"];
    totals["per_cut"]        = solvers;
    summary["solver"]        = totals;

    nlohmann::ordered_json json;
    json["langer_line_angle_deg"] = std::isnan(langer) ?
                                      nlohmann::ordered_json() :
                                      nlohmann::ordered_json(langer);
    json["skin_tension_N_per_m"]  = {{"x", tension[0]}, {"y", tension[1]}};
    if (incision.shape == Incision::Shape::disc)
      json.update(wound_entries["excision"]);
    else
      json.update(wound_entries);
    std::vector<double> gaps, areas;
    for (const WoundShape &w : final_wounds)
      {
        gaps.push_back(w.gap_mm);
        areas.push_back(w.area_mm2);
      }
    if (incision.shape == Incision::Shape::line)
      add_ratio(json, "gap", gaps);
    else if (incision.shape == Incision::Shape::ellipse)
      add_ratio(json, "area", areas);
    summary["wound"] = json;

    if (incision.excision())
      {
        // the freed skin relaxes to its stress-free state, whatever its
        // law: its area changes by 1 / s^2 (of the skin alone; with fat
        // attached it would shrink less)
        const double s  = parameters.layers.layer(0).prestretch;
        summary["disc"] = {{"area_change_pct", 100. * (1. / (s * s) - 1.)}};
      }
    if (!final_closures.empty())
      {
        nlohmann::ordered_json closed = closure_entries;
        std::vector<double>    forces;
        for (const ClosureState &state : final_closures)
          forces.push_back(state.mean_force_N());
        add_ratio(closed, "force", forces);
        summary["closure"] = closed;
      }
  }
} // namespace ssc
