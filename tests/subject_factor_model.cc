// The per-person subject factors of the in vivo identification
// (SubjectFactorModel), on the forearm trials' real covariates with
// synthetic log factors y = z . beta + noise:
// - without noise the fit recovers beta to round-off, for no information
//   (the intercept), covariates and the other sites' factor, predicts a
//   held-out subject exactly, and treats a subject without another site as
//   one at the training mean;
// - with Gaussian noise (sd 0.2) the 95 % intervals cover the true
//   coefficients in 95 % of 400 repetitions (0.93-0.97 allowed, the
//   binomial spread of 1,600 intervals is 0.0054);
// - too few training subjects, and a covariate that does not vary (all
//   subjects of one sex), are refused by name.

#include <boost/algorithm/string/trim.hpp>

#include <cmath>
#include <limits>
#include <random>

#include <ssc/identification/subject_factor_model.h>

#include "tests.h"

using namespace dealii;

namespace
{
  const std::string data_file =
    SOURCE_DIR "/../data/multis/indentation_trials.csv";

  /// Standard normal numbers from a Mersenne twister's raw output (Box-
  /// Muller; the standard distributions differ between libraries).
  class Normal
  {
  public:
    double
    operator()()
    {
      const double u1 = (generator() + 0.5) / 4294967296.;
      const double u2 = (generator() + 0.5) / 4294967296.;
      return std::sqrt(-2 * std::log(u1)) * std::cos(2 * M_PI * u2);
    }

  private:
    std::mt19937 generator{7};
  };

  /// The covariates' part of the synthetic log factor of @p trial: age
  /// per 10 years, male, BMI per 5, activity level.
  double
  covariate_part(const ssc::IndentationTrial &trial)
  {
    return -0.04 * trial.age / 10 + 0.3 * (trial.sex == "Male") +
           0.05 * trial.bmi / 5 - 0.1 * trial.activity_level;
  }

  /// Writes the message of @p e, as the user sees it.
  void
  print_refusal(const ExceptionBase &e)
  {
    std::ostringstream info;
    e.print_info(info);
    std::string message = info.str();
    boost::trim(message);
    deallog << "refused: " << message << std::endl;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();

  const auto trials = ssc::read_indentation_trials(data_file, {"LA_A"}).trials;
  // the other sites' factor enters in octaves: 0.6 per unit of log is
  // 0.6 log 2 per doubling
  const std::vector<double> beta = {-0.04, 0.3, 0.05, -0.1, 0.6 * std::log(2.)};
  // an other-site factor that varies from subject to subject
  std::vector<double> other;
  for (unsigned int i = 0; i < trials.size(); ++i)
    other.push_back(0.3 * std::sin(1.7 * i));
  const std::vector<ssc::IndentationTrial> training(trials.begin(),
                                                    trials.end() - 1);
  const std::vector<double> training_other(other.begin(), other.end() - 1);

  for (const auto information :
       {ssc::SubjectInformation::none,
        ssc::SubjectInformation::covariates,
        ssc::SubjectInformation::other_sites,
        ssc::SubjectInformation::covariates_and_other_sites})
    {
      const bool with_covariates = ssc::uses_covariates(information);
      const bool with_other      = ssc::uses_other_sites(information);
      const auto y_of            = [&](const unsigned int i) {
        return 0.2 + (with_covariates ? covariate_part(trials[i]) : 0.) +
               (with_other ? 0.6 * other[i] : 0.);
      };
      std::vector<double> y;
      for (unsigned int i = 0; i + 1 < trials.size(); ++i)
        y.push_back(y_of(i));
      ssc::SubjectFactorModel model(information);
      model.fit(training, y, training_other);
      double       error = 0;
      unsigned int j     = with_covariates ? 0 : 4;
      for (const auto &c : model.coefficients())
        error = std::max(error, std::abs(c.value - beta[j++]));
      const double prediction_error =
        std::abs(model.log_factor(trials.back(), other.back()) -
                 y_of(trials.size() - 1));
      // a subject without another site: as if it had the training mean
      double mean_other = 0;
      for (const double f : training_other)
        mean_other += f / training_other.size();
      const double no_other_error =
        std::abs(model.log_factor(trials.back(),
                                  std::numeric_limits<double>::quiet_NaN()) -
                 model.log_factor(trials.back(), mean_other));
      deallog << ssc::subject_information_key(information)
              << ": largest coefficient error "
              << (error < 1e-12 ? "below 1e-12" : std::to_string(error))
              << ", held-out prediction error "
              << (prediction_error < 1e-12 ? "below 1e-12" :
                                             std::to_string(prediction_error))
              << ", without another site as at the mean "
              << (no_other_error < 1e-12 ? "to 1e-12" : "NOT") << ", R^2 "
              << model.r_squared() << std::endl;
    }

  // interval coverage with noise
  Normal       normal;
  unsigned int covered = 0, intervals = 0;
  for (unsigned int repetition = 0; repetition < 400; ++repetition)
    {
      std::vector<double> y;
      for (unsigned int i = 0; i + 1 < trials.size(); ++i)
        y.push_back(0.2 + covariate_part(trials[i]) + 0.2 * normal());
      ssc::SubjectFactorModel model(ssc::SubjectInformation::covariates);
      model.fit(training, y, training_other);
      unsigned int j = 0;
      for (const auto &c : model.coefficients())
        {
          covered += c.lower <= beta[j] && beta[j] <= c.upper;
          ++intervals;
          ++j;
        }
    }
  const double coverage = double(covered) / intervals;
  deallog << "95 % intervals cover the truth in 0.93-0.97 of " << intervals
          << ": " << (coverage >= 0.93 && coverage <= 0.97 ? "yes" : "no")
          << std::endl;

  // refused
  std::vector<ssc::IndentationTrial> few(trials.begin(), trials.begin() + 5);
  std::vector<ssc::IndentationTrial> one_sex;
  for (const auto &trial : trials)
    if (trial.sex == "Female")
      one_sex.push_back(trial);
  for (const auto &set : {few, one_sex})
    try
      {
        ssc::SubjectFactorModel model(ssc::SubjectInformation::covariates);
        model.fit(set,
                  std::vector<double>(set.size(), 0.1),
                  std::vector<double>(set.size(), 0.));
        deallog << "not refused" << std::endl;
      }
    catch (const ExceptionBase &e)
      {
        print_refusal(e);
      }
}
