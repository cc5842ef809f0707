#include <deal.II/base/exceptions.h>

#include <boost/math/distributions/students_t.hpp>

#include <cmath>

#include <ssc/identification/subject_factor_model.h>

#include <Eigen/Dense>

namespace ssc
{
  using namespace dealii;

  std::string
  subject_information_key(const SubjectInformation information)
  {
    switch (information)
      {
        case SubjectInformation::none:
          return "calibrated";
        case SubjectInformation::covariates:
          return "covariates";
        case SubjectInformation::other_sites:
          return "cross_site";
        default:
          return "covariates_and_cross_site";
      }
  }


  SubjectFactorModel::SubjectFactorModel(const SubjectInformation information)
    : information(information)
  {}


  std::vector<std::string>
  SubjectFactorModel::feature_names() const
  {
    std::vector<std::string> names;
    if (uses_covariates(information))
      names = {"age per 10 years",
               "male",
               "BMI per 5 kg/m^2",
               "activity level per step"};
    if (uses_other_sites(information))
      names.emplace_back("other sites' factor doubled");
    return names;
  }


  std::vector<double>
  SubjectFactorModel::raw_features(const IndentationTrial &trial,
                                   const double other_site_factor) const
  {
    std::vector<double> z = {1.};
    if (uses_covariates(information))
      {
        z.push_back(trial.age / 10.);
        z.push_back(trial.sex == "Male" ? 1. : 0.);
        z.push_back(trial.bmi / 5.);
        z.push_back(trial.activity_level);
      }
    // in octaves: exp(coefficient) is the factor here when the other
    // sites' factor doubles
    if (uses_other_sites(information))
      z.push_back(other_site_factor / std::log(2.));
    return z;
  }


  void
  SubjectFactorModel::fit(const std::vector<IndentationTrial> &trials,
                          const std::vector<double>           &log_factors,
                          const std::vector<double> &other_site_factors)
  {
    AssertThrow(log_factors.size() == trials.size() &&
                  other_site_factors.size() == trials.size(),
                ExcMessage("One log factor and one other-site factor per "
                           "trial."));
    const unsigned int n = trials.size();
    const unsigned int p = feature_names().size() + 1;
    AssertThrow(n > p,
                ExcMessage(
                  "A per-person model with " + std::to_string(p) +
                  " coefficients needs more than " + std::to_string(p) +
                  " training subjects at a site (" + std::to_string(n) +
                  " here): raise Identification/Training fraction or "
                  "add subjects."));
    // subjects without another site: the mean of those with one
    double       known_sum = 0;
    unsigned int known     = 0;
    for (const double f : other_site_factors)
      if (std::isfinite(f))
        {
          known_sum += f;
          ++known;
        }
    const double fill = known > 0 ? known_sum / known : 0.;
    other_site_fill   = fill;

    Eigen::MatrixXd Z(n, p);
    Eigen::VectorXd y(n);
    for (unsigned int i = 0; i < n; ++i)
      {
        const double f =
          std::isfinite(other_site_factors[i]) ? other_site_factors[i] : fill;
        const std::vector<double> z = raw_features(trials[i], f);
        for (unsigned int j = 0; j < p; ++j)
          Z(i, j) = z[j];
        y(i) = log_factors[i];
      }
    means.assign(p, 0.);
    for (unsigned int j = 1; j < p; ++j)
      {
        means[j] = Z.col(j).mean();
        Z.col(j).array() -= means[j];
      }
    // columnwise pivoted QR: a covariate that does not vary (all one sex)
    // leaves Z rank deficient, which is refused by name below
    const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(Z);
    AssertThrow(qr.rank() == p,
                ExcMessage("The training subjects at a site do not determine "
                           "the per-person model: a covariate does not vary "
                           "among them (e.g. all of one sex)."));
    const Eigen::VectorXd b          = qr.solve(y);
    const Eigen::VectorXd residual   = y - Z * b;
    const double          variance   = residual.squaredNorm() / (n - p);
    const Eigen::MatrixXd covariance = variance * (Z.transpose() * Z).inverse();
    const double          t_quantile = boost::math::quantile(
      boost::math::complement(boost::math::students_t(n - p), 0.025));
    beta.resize(p);
    lower.resize(p);
    upper.resize(p);
    for (unsigned int j = 0; j < p; ++j)
      {
        beta[j]  = b(j);
        lower[j] = b(j) - t_quantile * std::sqrt(covariance(j, j));
        upper[j] = b(j) + t_quantile * std::sqrt(covariance(j, j));
      }
    // log factors that do not vary (to round-off) leave nothing to explain
    const double total = (y.array() - y.mean()).square().sum();
    explained_fraction = total > 1e-20 * y.squaredNorm() ?
                           1. - residual.squaredNorm() / total :
                           0.;
  }


  double
  SubjectFactorModel::log_factor(const IndentationTrial &trial,
                                 const double other_site_factor) const
  {
    AssertThrow(!beta.empty(),
                ExcMessage("SubjectFactorModel::log_factor before fit()."));
    // no other site: the training subjects' mean, i.e. no information
    const double f =
      std::isfinite(other_site_factor) ? other_site_factor : other_site_fill;
    const std::vector<double> z = raw_features(trial, f);
    double                    y = beta[0];
    for (unsigned int j = 1; j < z.size(); ++j)
      y += beta[j] * (z[j] - means[j]);
    return y;
  }


  std::vector<FactorCoefficient>
  SubjectFactorModel::coefficients() const
  {
    const std::vector<std::string> names = feature_names();
    std::vector<FactorCoefficient> c;
    for (unsigned int j = 0; j < names.size() && j + 1 < beta.size(); ++j)
      c.push_back({names[j], beta[j + 1], lower[j + 1], upper[j + 1]});
    return c;
  }
} // namespace ssc
