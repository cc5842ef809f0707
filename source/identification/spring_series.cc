#include <deal.II/base/exceptions.h>

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/householder.h>
#include <deal.II/lac/vector.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <set>
#include <sstream>

#include <ssc/identification/spring_series.h>

namespace ssc
{
  using namespace dealii;

  SpringSeriesModel::SpringSeriesModel(const std::array<double, 3> &moduli)
    : layer_moduli(moduli)
  {
    for (const double E : moduli)
      AssertThrow(E > 0,
                  ExcMessage("The springs' moduli must be positive (MPa)."));
  }


  SpringSeriesModel
  SpringSeriesModel::fit_to_stiffness(
    const std::vector<IndentationTrial> &trials)
  {
    AssertThrow(trials.size() >= 3,
                ExcMessage("Fitting three layer moduli needs at least three "
                           "trials, got " +
                           std::to_string(trials.size()) + "."));
    FullMatrix<double> design(trials.size(), 3);
    Vector<double>     compliance_times_area(trials.size());
    for (unsigned int j = 0; j < trials.size(); ++j)
      {
        const auto t = trials[j].layer_thicknesses();
        for (unsigned int i = 0; i < 3; ++i)
          design(j, i) = t[i];
        compliance_times_area(j) =
          trials[j].probe_area / trials[j].surface_stiffness;
      }
    Vector<double> layer_compliances(3);
    Householder<double>(design).least_squares(layer_compliances,
                                              compliance_times_area);
    std::array<double, 3> moduli;
    for (unsigned int i = 0; i < 3; ++i)
      {
        std::ostringstream message;
        message << "Springs in series: the fitted compliance of the "
                << trial_layer_names[i] << " layer is " << layer_compliances(i)
                << " mm^2/N, not positive: these " << trials.size()
                << " trials do not determine its modulus.";
        AssertThrow(layer_compliances(i) > 0, ExcMessage(message.str()));
        moduli[i] = 1. / layer_compliances(i);
      }
    return SpringSeriesModel(moduli);
  }


  SpringSeriesModel
  SpringSeriesModel::fit_to_layer_strains(
    const std::vector<IndentationTrial> &trials)
  {
    AssertThrow(!trials.empty(),
                ExcMessage("Fitting the layer moduli needs trials."));
    std::array<double, 3> strain_times_pressure{};
    double                pressure_squared = 0;
    for (const auto &trial : trials)
      {
        const double pressure = trial.max_force / trial.probe_area;
        const auto   strains  = trial.layer_strains();
        for (unsigned int i = 0; i < 3; ++i)
          strain_times_pressure[i] += strains[i] * pressure;
        pressure_squared += pressure * pressure;
      }
    const std::array<const char *, 3> strain_columns = {
      {"SkinStrain", "FatStrain", "MuscleStrain"}};
    std::array<double, 3> moduli;
    for (unsigned int i = 0; i < 3; ++i)
      {
        if (!(strain_times_pressure[i] > 0))
          {
            // name the data the user can check: the trials' lines
            std::ostringstream message;
            message
              << "Springs in series: the " << trial_layer_names[i]
              << " layer's compressions (column " << strain_columns[i]
              << " of Identification/Data file) do not grow with the pressure "
                 "over the training trials on lines";
            for (const auto &trial : trials)
              message << ' ' << trial.line << " (" << trial.layer_strains()[i]
                      << ')';
            message << ": its modulus is undetermined; check these values "
                       "(compression is positive).";
            AssertThrow(false, ExcMessage(message.str()));
          }
        moduli[i] = pressure_squared / strain_times_pressure[i];
      }
    return SpringSeriesModel(moduli);
  }


  double
  SpringSeriesModel::stiffness(const IndentationTrial &trial) const
  {
    const auto t          = trial.layer_thicknesses();
    double     compliance = 0; // mm per MPa of pressure
    for (unsigned int i = 0; i < 3; ++i)
      compliance += t[i] / layer_moduli[i];
    return trial.probe_area / compliance;
  }


  std::array<double, 3>
  SpringSeriesModel::layer_strains(const IndentationTrial &trial) const
  {
    const double          pressure = trial.max_force / trial.probe_area;
    std::array<double, 3> strains;
    for (unsigned int i = 0; i < 3; ++i)
      strains[i] = pressure / layer_moduli[i];
    return strains;
  }


  TrialSplit
  split_by_subject(const std::vector<IndentationTrial> &trials,
                   const double                         training_fraction,
                   const unsigned int                   seed)
  {
    AssertThrow(training_fraction > 0 && training_fraction < 1,
                ExcMessage("The training fraction must lie strictly between "
                           "0 and 1."));
    std::set<std::string> subject_set;
    for (const auto &trial : trials)
      subject_set.insert(trial.subject);
    std::vector<std::string> subjects(subject_set.begin(), subject_set.end());
    // Fisher-Yates on the generator's raw output: std::shuffle and the
    // standard distributions differ between library implementations
    std::mt19937 generator(seed);
    for (std::size_t i = subjects.size(); i > 1; --i)
      std::swap(subjects[i - 1], subjects[generator() % i]);
    const std::size_t n_training =
      std::lround(training_fraction * subjects.size());
    AssertThrow(n_training >= 1 && n_training < subjects.size(),
                ExcMessage("A training fraction of " +
                           std::to_string(training_fraction) + " of " +
                           std::to_string(subjects.size()) +
                           " subjects leaves one of the two sets empty."));
    const std::set<std::string> training(subjects.begin(),
                                         subjects.begin() + n_training);
    TrialSplit                  split;
    for (const auto &trial : trials)
      (training.count(trial.subject) ? split.training : split.held_out)
        .push_back(trial);
    return split;
  }


  std::vector<TrialPrediction>
  SpringSeriesModel::predict(const std::vector<IndentationTrial> &trials) const
  {
    std::vector<TrialPrediction> predictions;
    for (const auto &trial : trials)
      predictions.push_back({stiffness(trial), layer_strains(trial)});
    return predictions;
  }
} // namespace ssc
