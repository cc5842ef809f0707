#ifndef ssc_identification_spring_series_h
#define ssc_identification_spring_series_h

#include <array>
#include <vector>

#include <ssc/identification/indentation_trials.h>
#include <ssc/identification/prediction_errors.h>

namespace ssc
{
  /**
   * The baseline of the in vivo identification: skin, fat and muscle as
   * springs in series under the probe (Neumann et al., PLoS One
   * 18:e0284721, 2023; Doherty 2022, eq. 3), each layer in uniaxial
   * compression by the mean probe pressure: A / k = sum_i t_i / E_i. It
   * ignores the load's lateral spread, so its moduli are apparent ones;
   * the finite-element model is measured against its held-out errors.
   */
  class SpringSeriesModel
  {
  public:
    /// Fits 1/E_i by linear least squares of A/k against the thicknesses
    /// over @p trials (surface stiffnesses k, probe areas A), as Neumann et
    /// al. did. Throws if a fitted compliance is not positive (the data do
    /// not determine that layer's modulus).
    static SpringSeriesModel
    fit_to_stiffness(const std::vector<IndentationTrial> &trials);

    /// Fits each 1/E_i by least squares of the layer's measured strains
    /// against the pressures at the largest force, through the origin.
    static SpringSeriesModel
    fit_to_layer_strains(const std::vector<IndentationTrial> &trials);

    /// A model with the given moduli (skin, fat, muscle), MPa.
    explicit SpringSeriesModel(const std::array<double, 3> &moduli);

    /// Skin, fat, muscle moduli, MPa.
    const std::array<double, 3> &
    moduli() const
    {
      return layer_moduli;
    }

    /// Surface stiffness of @p trial's layers under its probe, N/mm.
    double
    stiffness(const IndentationTrial &trial) const;

    /// Each layer's compressive strain at the trial's largest force.
    std::array<double, 3>
    layer_strains(const IndentationTrial &trial) const;

    /// Both for each of @p trials.
    std::vector<TrialPrediction>
    predict(const std::vector<IndentationTrial> &trials) const;

  private:
    std::array<double, 3> layer_moduli;
  };

  /// Training and held-out trials, split by subject: all trials of a
  /// subject are on the same side.
  struct TrialSplit
  {
    std::vector<IndentationTrial> training;
    std::vector<IndentationTrial> held_out;
  };

  /**
   * Shuffles the subjects of @p trials with a Mersenne twister seeded by
   * @p seed (the same split on every platform) and puts the first
   * round(@p training_fraction x subjects) of them, with all their trials,
   * in the training set.
   */
  TrialSplit
  split_by_subject(const std::vector<IndentationTrial> &trials,
                   const double                         training_fraction,
                   const unsigned int                   seed);

  /// The spring model's errors on @p trials.
  inline PredictionErrors
  prediction_errors(const SpringSeriesModel             &model,
                    const std::vector<IndentationTrial> &trials)
  {
    return prediction_errors(model.predict(trials), trials);
  }
} // namespace ssc

#endif
