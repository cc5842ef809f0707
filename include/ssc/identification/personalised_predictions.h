#ifndef ssc_identification_personalised_predictions_h
#define ssc_identification_personalised_predictions_h

#include <string>
#include <vector>

#include <ssc/identification/identification_record.h>
#include <ssc/identification/subject_factor_model.h>

namespace ssc
{
  /// One per-person method's models and predictions at every site.
  struct PersonalisedPredictions
  {
    SubjectInformation information;
    /// Per site, in the run's order: the fitted model, the predictions
    /// of the held-out trials and the fitted values of the training ones.
    std::vector<SubjectFactorModel>           models;
    std::vector<std::vector<TrialPrediction>> held_out, training;
    /// Why the method could not be fitted (too few training subjects at a
    /// site, a covariate that does not vary); empty if it was.
    std::string not_determined;
  };

  /**
   * The per-person methods (SubjectFactorModel: covariates, the subject's
   * other sites, both), and their reference without per-person
   * information (one factor for all: the population model recalibrated to
   * the training stiffnesses), on top of each site's population model in
   * @p sites. The log factor of a trial is log(measured stiffness over
   * its site's population prediction); a subject's other-site factor at a
   * site is the mean of its log factors at the run's other sites. The split
   * is by subject over all sites, so a held-out subject's trials at other
   * sites were not fitted there either: it is a new person who was
   * measured at those sites. A method that a site's training subjects do
   * not determine is returned with its reason and no predictions.
   */
  std::vector<PersonalisedPredictions>
  personalised_predictions(const std::vector<SiteFit> &sites);

  /**
   * The correlation between sites of the subjects' log factors (every
   * subject measured at both; NaN where fewer than three are): how much
   * of a person's stiffness at one site, beyond what the population model
   * explains, is seen at another. Row and column in the order of
   * @p sites.
   */
  std::vector<std::vector<double>>
  site_correlations(const std::vector<SiteFit> &sites);
} // namespace ssc

#endif
