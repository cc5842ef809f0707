#include <deal.II/base/exceptions.h>

#include <cmath>
#include <limits>
#include <map>

#include <ssc/base/user_message.h>
#include <ssc/identification/personalised_predictions.h>

namespace ssc
{
  using namespace dealii;

  namespace
  {
    /// Every subject's log factor at each site (the site's index).
    using LogFactors = std::map<std::string, std::map<unsigned int, double>>;

    LogFactors
    log_factors(const std::vector<SiteFit> &sites)
    {
      LogFactors factors;
      for (unsigned int k = 0; k < sites.size(); ++k)
        for (const auto &[trials, predictions] :
             {std::make_pair(&sites[k].split.training, &sites[k].training),
              std::make_pair(&sites[k].split.held_out, &sites[k].held_out)})
          for (unsigned int t = 0; t < trials->size(); ++t)
            factors[(*trials)[t].subject][k] = std::log(
              (*trials)[t].surface_stiffness / (*predictions)[t].stiffness);
      return factors;
    }

    /// The mean log factor of @p subject at the sites other than @p site;
    /// NaN if it has none.
    double
    other_site_factor(const LogFactors  &factors,
                      const std::string &subject,
                      const unsigned int site)
    {
      double       sum = 0;
      unsigned int n   = 0;
      for (const auto &[k, y] : factors.at(subject))
        if (k != site)
          {
            sum += y;
            ++n;
          }
      return n > 0 ? sum / n : std::numeric_limits<double>::quiet_NaN();
    }

    /// The population predictions @p population scaled by the subject
    /// factors of @p model: stiffness times m, strains over m.
    std::vector<TrialPrediction>
    scaled(const SubjectFactorModel            &model,
           const std::vector<IndentationTrial> &trials,
           const std::vector<TrialPrediction>  &population,
           const LogFactors                    &factors,
           const unsigned int                   site)
    {
      std::vector<TrialPrediction> predictions = population;
      for (unsigned int t = 0; t < trials.size(); ++t)
        {
          const double m = std::exp(model.log_factor(
            trials[t], other_site_factor(factors, trials[t].subject, site)));
          predictions[t].stiffness *= m;
          for (double &strain : predictions[t].layer_strains)
            strain /= m;
        }
      return predictions;
    }
  } // namespace


  std::vector<PersonalisedPredictions>
  personalised_predictions(const std::vector<SiteFit> &sites)
  {
    const LogFactors                     factors = log_factors(sites);
    std::vector<PersonalisedPredictions> methods;
    for (const SubjectInformation information :
         {SubjectInformation::none,
          SubjectInformation::covariates,
          SubjectInformation::other_sites,
          SubjectInformation::covariates_and_other_sites})
      {
        // the other sites' information needs another site
        if (uses_other_sites(information) && sites.size() < 2)
          continue;
        PersonalisedPredictions method{information, {}, {}, {}, {}};
        for (unsigned int k = 0; k < sites.size(); ++k)
          try
            {
              const SiteFit      &s = sites[k];
              std::vector<double> y, other;
              for (const IndentationTrial &trial : s.split.training)
                {
                  y.push_back(factors.at(trial.subject).at(k));
                  other.push_back(other_site_factor(factors, trial.subject, k));
                }
              SubjectFactorModel model(information);
              model.fit(s.split.training, y, other);
              method.held_out.push_back(
                scaled(model, s.split.held_out, s.held_out, factors, k));
              method.training.push_back(
                scaled(model, s.split.training, s.training, factors, k));
              method.models.push_back(std::move(model));
            }
          catch (const ExceptionBase &e)
            {
              method = {information, {}, {}, {}, user_message(e)};
              break;
            }
        methods.push_back(std::move(method));
      }
    return methods;
  }


  std::vector<std::vector<double>>
  site_correlations(const std::vector<SiteFit> &sites)
  {
    const LogFactors                 factors = log_factors(sites);
    const unsigned int               n_sites = sites.size();
    std::vector<std::vector<double>> r(
      n_sites,
      std::vector<double>(n_sites, std::numeric_limits<double>::quiet_NaN()));
    for (unsigned int a = 0; a < n_sites; ++a)
      for (unsigned int b = 0; b < n_sites; ++b)
        {
          std::vector<double> x, y;
          for (const auto &[subject, at] : factors)
            if (at.count(a) && at.count(b))
              {
                x.push_back(at.at(a));
                y.push_back(at.at(b));
              }
          const unsigned int n = x.size();
          if (n < 3)
            continue;
          double mx = 0, my = 0;
          for (unsigned int i = 0; i < n; ++i)
            {
              mx += x[i] / n;
              my += y[i] / n;
            }
          double sxy = 0, sxx = 0, syy = 0;
          for (unsigned int i = 0; i < n; ++i)
            {
              sxy += (x[i] - mx) * (y[i] - my);
              sxx += (x[i] - mx) * (x[i] - mx);
              syy += (y[i] - my) * (y[i] - my);
            }
          if (sxx > 0 && syy > 0)
            r[a][b] = sxy / std::sqrt(sxx * syy);
        }
    return r;
  }
} // namespace ssc
