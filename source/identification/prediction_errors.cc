#include <deal.II/base/exceptions.h>

#include <algorithm>
#include <cmath>

#include <ssc/identification/prediction_errors.h>

namespace ssc
{
  using namespace dealii;

  namespace
  {
    double
    relative_error_pct(const double predicted, const double measured)
    {
      return 100. * std::abs(predicted - measured) / std::abs(measured);
    }
  } // namespace


  double
  median(std::vector<double> values)
  {
    AssertThrow(!values.empty(), ExcMessage("The median of no values."));
    const std::size_t n = values.size();
    std::nth_element(values.begin(), values.begin() + n / 2, values.end());
    const double upper = values[n / 2];
    if (n % 2 == 1)
      return upper;
    return 0.5 *
           (upper + *std::max_element(values.begin(), values.begin() + n / 2));
  }


  PredictionErrors
  prediction_errors(const std::vector<TrialPrediction>  &predictions,
                    const std::vector<IndentationTrial> &trials)
  {
    AssertThrow(predictions.size() == trials.size(),
                ExcMessage("One prediction per trial is needed."));
    std::vector<double>                stiffness, pooled;
    std::array<std::vector<double>, 3> per_layer;
    for (unsigned int t = 0; t < trials.size(); ++t)
      {
        stiffness.push_back(relative_error_pct(predictions[t].stiffness,
                                               trials[t].surface_stiffness));
        const auto measured = trials[t].layer_strains();
        for (unsigned int i = 0; i < 3; ++i)
          {
            per_layer[i].push_back(
              relative_error_pct(predictions[t].layer_strains[i], measured[i]));
            pooled.push_back(per_layer[i].back());
          }
      }
    PredictionErrors errors;
    errors.stiffness_pct = median(stiffness);
    for (unsigned int i = 0; i < 3; ++i)
      errors.layer_strain_pct[i] = median(per_layer[i]);
    errors.pooled_layer_strain_pct = median(pooled);
    return errors;
  }
} // namespace ssc
