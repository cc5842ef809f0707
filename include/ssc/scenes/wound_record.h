#ifndef ssc_scenes_wound_record_h
#define ssc_scenes_wound_record_h

#include <deal.II/base/conditional_ostream.h>

#include <nlohmann/json.hpp>

#include <array>
#include <sstream>
#include <string>
#include <vector>

#include <ssc/output/run_output.h>
#include <ssc/scenes/closure.h>
#include <ssc/scenes/parameters.h>
#include <ssc/scenes/wound.h>

namespace ssc
{
  using namespace dealii;

  /**
   * The incision scene's record: for each model (a cut along x or y, a
   * disc, an ellipse along x or y) the wound after each pre-tension step,
   * the closure after each suture step, the solvers' summaries, the
   * progress lines; from them wound.csv, wound_lips.csv, closure.csv and
   * the scene's part of summary.json ("wound", "disc", "closure").
   */
  class WoundRecord
  {
  public:
    /// @p langer_line_angle: the angle of Langer's lines at the patch
    /// centre (degrees from x), NaN where the skin has none.
    WoundRecord(const Parameters   &parameters,
                const double        langer_line_angle,
                ConditionalOStream &pcout);

    /// Starts the model of @p incision and prints its line.
    void
    begin_model(const Incision &incision);

    /// Records the wound at pre-tension step @p step (fraction @p
    /// fraction).
    void
    record_wound(const unsigned int step,
                 const double       fraction,
                 const WoundShape  &wound);

    /// Records the closure at suture step @p step.
    void
    record_closure(const unsigned int step, const ClosureState &state);

    /// Ends the model: its solvers' summaries (@p closure_solver null
    /// without closure).
    void
    end_model(const nlohmann::ordered_json &solver,
              const nlohmann::ordered_json &closure_solver);

    /// Writes wound.csv, wound_lips.csv and (with closure) closure.csv.
    void
    write_tables(RunOutput &output) const;

    /// Adds "wound", "disc" (excisions), "closure" (with sutures) and the
    /// solvers' totals to @p summary; @p tension is the skin's far-field
    /// tension along x and y, N/m.
    void
    add_to_summary(nlohmann::ordered_json      &summary,
                   const std::array<double, 2> &tension) const;

    /// The wounds of the models at full pre-tension.
    const std::vector<WoundShape> &
    wounds() const
    {
      return final_wounds;
    }

  private:
    /// "along" or "across" Langer's lines for the model along @p
    /// direction, "" without lines.
    std::string
    relation(const unsigned int direction) const;

    /// The ratio of @p value across to along Langer's lines (or x to y)
    /// over the two models, with its key (@p name + "_ratio_...").
    void
    add_ratio(nlohmann::ordered_json    &json,
              const std::string         &name,
              const std::vector<double> &values) const;

    const Parameters         &parameters;
    const double              langer;
    ConditionalOStream       &pcout;
    Incision                  incision;
    std::string               name, key;
    WoundShape                wound;
    ClosureState              closure;
    std::vector<WoundShape>   final_wounds;
    std::vector<ClosureState> final_closures;
    nlohmann::ordered_json    wound_entries, closure_entries, solvers;
    std::ostringstream        wound_table, lips_table, closure_table;
  };
} // namespace ssc

#endif
