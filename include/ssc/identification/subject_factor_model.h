#ifndef ssc_identification_subject_factor_model_h
#define ssc_identification_subject_factor_model_h

#include <string>
#include <vector>

#include <ssc/identification/indentation_trials.h>

namespace ssc
{
  /// What a per-person prediction knows about a subject.
  enum class SubjectInformation
  {
    /// Nothing: one factor for every subject, the population model
    /// recalibrated to the training stiffnesses (the reference that tells
    /// what the per-person information adds).
    none,
    /// Age, sex, body-mass index and activity level.
    covariates,
    /// The subject's own trials at the run's other sites.
    other_sites,
    /// Both.
    covariates_and_other_sites
  };

  /// Whether @p information includes the subject's covariates.
  inline bool
  uses_covariates(const SubjectInformation information)
  {
    return information == SubjectInformation::covariates ||
           information == SubjectInformation::covariates_and_other_sites;
  }

  /// Whether @p information includes the subject's other sites.
  inline bool
  uses_other_sites(const SubjectInformation information)
  {
    return information == SubjectInformation::other_sites ||
           information == SubjectInformation::covariates_and_other_sites;
  }

  /// The name of @p information in summary.json ("calibrated",
  /// "covariates", "cross_site", "covariates_and_cross_site").
  std::string
  subject_information_key(const SubjectInformation information);

  /// One coefficient of a SubjectFactorModel with its 95 % interval.
  struct FactorCoefficient
  {
    /// What it multiplies, with its unit (e.g. "age per 10 years"); the
    /// values are log factors on the moduli per unit.
    std::string name;
    double      value = 0, lower = 0, upper = 0;
  };

  /**
   * A subject's stiffness factor at one site from what is known about the
   * subject. The population model (one set of layer moduli per site)
   * predicts a stiffness K_pop for every trial; the per-person model
   * multiplies all of that subject's layer moduli by m = exp(z . beta),
   * with z the subject's features and beta fitted on the training
   * subjects. The forward model is homogeneous of degree one in the
   * moduli, so its stiffness for those moduli is exactly m K_pop (and each
   * strain the population's over m): the least-squares fit of the log
   * stiffness with the finite-element model inside is the linear
   * regression of y = log(K_measured / K_pop) on z, solved here without a
   * further forward solve.
   *
   * Features (the intercept first, each centred on the training subjects'
   * mean so that the intercept is the typical subject's log factor):
   * - covariates: age per 10 years, male (1) against female (0), body-mass
   *   index per 5 kg/m^2, activity level per step (sedentary, moderately,
   *   active);
   * - other sites: the mean of y over the subject's trials at the run's
   *   other sites (each against its own site's population model), in
   *   octaves (over log 2): a subject stiff at one site is predicted stiff
   *   at another, by as much as the training subjects show. A subject
   *   without another trial gets the training mean (no information).
   * So exp(coefficient) is the factor on the moduli per unit of a feature
   * (per 10 years, male against female, per 5 kg/m^2, per activity step,
   * per doubling of the other sites' factor).
   * The 95 % intervals are the ordinary least-squares ones (residual
   * variance times (Z^T Z)^-1, Student's t quantile).
   */
  class SubjectFactorModel
  {
  public:
    explicit SubjectFactorModel(const SubjectInformation information);

    /**
     * Fits to @p trials (one site's training trials) with @p log_factors
     * y and @p other_site_factors (the mean y of each trial's subject at
     * the other sites, NaN where it has none; unused for covariates).
     * Throws if there are not more trials than coefficients.
     */
    void
    fit(const std::vector<IndentationTrial> &trials,
        const std::vector<double>           &log_factors,
        const std::vector<double>           &other_site_factors);

    /// The log factor log m of @p trial's subject.
    double
    log_factor(const IndentationTrial &trial,
               const double            other_site_factor) const;

    /// The coefficients without the intercept, with their intervals.
    std::vector<FactorCoefficient>
    coefficients() const;

    /// The fraction of the training log factors' variance explained.
    double
    r_squared() const
    {
      return explained_fraction;
    }

  private:
    /// The features of one trial, uncentred, intercept first.
    std::vector<double>
    raw_features(const IndentationTrial &trial,
                 const double            other_site_factor) const;

    /// The names of the features after the intercept.
    std::vector<std::string>
    feature_names() const;

    SubjectInformation  information;
    std::vector<double> means, beta, lower, upper;
    /// The other sites' factor of a subject without another site: the
    /// training subjects' mean.
    double other_site_fill    = 0;
    double explained_fraction = 0;
  };
} // namespace ssc

#endif
