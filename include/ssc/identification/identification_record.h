#ifndef ssc_identification_identification_record_h
#define ssc_identification_identification_record_h

#include <nlohmann/json.hpp>

#include <array>
#include <sstream>
#include <string>
#include <vector>

#include <ssc/identification/indentation_trials.h>
#include <ssc/identification/layer_moduli_fit.h>
#include <ssc/identification/prediction_errors.h>
#include <ssc/identification/spring_series.h>
#include <ssc/identification/subject_factor_model.h>
#include <ssc/scenes/scene_run.h>

namespace ssc
{
  /// What the identification found at one site.
  struct SiteFit
  {
    TrialSplit split;
    /// The fit's start: the springs' strain moduli scaled to the median
    /// stiffness.
    std::array<double, 3> initial{};
    ModuliFit             fit;
    /// The baseline, springs in series, and how it was fitted.
    std::array<double, 3> springs_moduli{};
    std::string           baseline_model;
    /// Predictions of the model and of the springs.
    std::vector<TrialPrediction> held_out, training;
    std::vector<TrialPrediction> held_out_springs, training_springs;
  };


  struct PersonalisedPredictions;

  /**
   * The identification's record: per site the fit, the predictions and
   * their errors, pooled over the sites the held-out trials; from them
   * identification.csv, per_subject_moduli.csv and the identification's
   * part of summary.json.
   */
  class IdentificationRecord
  {
  public:
    IdentificationRecord();

    /// Records @p site's fit and predictions; prints their errors.
    void
    add_site(const std::string              &site,
             const SiteFit                  &site_fit,
             const IdentificationParameters &parameters,
             ConditionalOStream             &pcout);

    /// Records the per-subject fits @p rows of @p site's @p trials.
    void
    add_per_subject(const std::string                        &site,
                    const std::vector<IndentationTrial>      &trials,
                    const std::vector<std::array<double, 4>> &rows,
                    ConditionalOStream                       &pcout);

    /**
     * Records the per-person @p methods built on the population models of
     * @p sites (named @p site_names): their held-out errors pooled and per
     * site, their coefficients and explained fractions, the correlation of
     * the subjects' log factors between sites, and every trial's
     * predictions (person_predictions.csv); prints their errors.
     */
    void
    add_personalised(const std::vector<PersonalisedPredictions> &methods,
                     const std::vector<SiteFit>                 &sites,
                     const std::vector<std::string>             &site_names,
                     ConditionalOStream                         &pcout);
    /// Records @p site's wall time (s).
    void
    add_wall_time(const std::string &site, const double seconds);

    /// The size of one forward model, for the summary.
    void
    set_model_size(const unsigned int dofs, const unsigned int cells);

    /// Whether the model size is known yet.
    bool
    has_model_size() const
    {
      return dofs > 0;
    }

    /// Writes the tables and summary.json into @p scene's folder.
    void
    write(SceneRun &scene, const IdentificationParameters &parameters) const;

  private:
    nlohmann::ordered_json        identification, per_site, personalised;
    std::vector<IndentationTrial> all_held_out;
    std::vector<TrialPrediction>  all_model, all_springs;
    std::ostringstream            csv, subject_csv, person_csv;
    unsigned int                  dofs = 0, cells = 0;
  };
} // namespace ssc

#endif
