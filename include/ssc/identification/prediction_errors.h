#ifndef ssc_identification_prediction_errors_h
#define ssc_identification_prediction_errors_h

#include <array>
#include <vector>

#include <ssc/identification/indentation_trials.h>

namespace ssc
{
  /// What a model predicts for one trial: the surface stiffness (N/mm)
  /// and each layer's compressive strain at the trial's largest force.
  struct TrialPrediction
  {
    double                stiffness = 0;
    std::array<double, 3> layer_strains{};
  };

  /// Median absolute relative errors (%) of predicted against measured
  /// values: the surface stiffness, and each layer's strain (skin, fat,
  /// muscle) and all three pooled.
  struct PredictionErrors
  {
    double                stiffness_pct = 0;
    std::array<double, 3> layer_strain_pct{};
    double                pooled_layer_strain_pct = 0;
  };

  /// The errors of @p predictions (one per trial) on @p trials.
  PredictionErrors
  prediction_errors(const std::vector<TrialPrediction>  &predictions,
                    const std::vector<IndentationTrial> &trials);

  /// The median of @p values (not empty).
  double
  median(std::vector<double> values);
} // namespace ssc

#endif
