#include <deal.II/base/timer.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <limits>
#include <set>
#include <sstream>

#include <ssc/base/round_robin.h>
#include <ssc/identification/identification_record.h>
#include <ssc/identification/identification_scene.h>
#include <ssc/identification/personalised_predictions.h>
#include <ssc/identification/probe_forward_model.h>
#include <ssc/scenes/scene_run.h>

namespace ssc
{
  namespace
  {
    /**
     * Every subject's moduli fitted to that subject's own trial (on this
     * rank's share of the trials, each fit on this process alone), from
     * the population's. One trial determines a layer's modulus only
     * through that layer's strain: the moduli fitted are the population's
     * fitted ones whose strain is among the fitted data, the others stay at
     * the population's. One row per trial (skin, fat, muscle moduli, then 1
     * if the fit converged), NaN where a fit failed.
     */
    std::vector<std::array<double, 4>>
    per_subject_fits(const ProbeForwardModel             &model,
                     const IdentificationParameters      &parameters,
                     const std::vector<IndentationTrial> &trials,
                     const std::array<double, 3>         &population,
                     const MPI_Comm                       mpi_communicator)
    {
      IdentificationParameters own_parameters = parameters;
      const auto               layers         = parameters.fitted_layers();
      const auto               data = parameters.fitted_measurements();
      own_parameters.fitted_moduli.clear();
      for (unsigned int l = 0; l < 3; ++l)
        if (layers[l] && data[l + 1])
          own_parameters.fitted_moduli.emplace_back(trial_layer_names[l]);
      AssertThrow(!own_parameters.fitted_moduli.empty(),
                  ExcMessage("Identification/Per-subject fits: no fitted "
                             "modulus has its layer's strain among the "
                             "Fitted data, which one trial needs to "
                             "determine it."));
      const LayerModuliFit own(model, own_parameters, MPI_COMM_SELF);
      ConditionalOStream   silent(std::cout, false);
      const auto           values =
        compute_round_robin(trials.size(),
                            4,
                            mpi_communicator,
                            [&](const unsigned int t, double *out) {
                              try
                                {
                                  const ModuliFit fit =
                                    own.fit({trials[t]}, population, silent);
                                  for (unsigned int l = 0; l < 3; ++l)
                                    out[l] = fit.moduli[l];
                                  out[3] = fit.converged;
                                }
                              catch (const std::exception &)
                                {
                                  // a forward model the fit drove out of range:
                                  // no fit
                                  for (unsigned int l = 0; l < 3; ++l)
                                    out[l] =
                                      std::numeric_limits<double>::quiet_NaN();
                                }
                            });
      std::vector<std::array<double, 4>> rows(trials.size());
      for (unsigned int t = 0; t < trials.size(); ++t)
        for (unsigned int k = 0; k < 4; ++k)
          rows[t][k] = values[4 * t + k];
      return rows;
    }


    /// The trials of @p site in @p data (read from @p path); throws if
    /// there is none.
    std::vector<IndentationTrial>
    site_trials(const IndentationData &data,
                const std::string     &site,
                const std::string     &path)
    {
      std::vector<IndentationTrial> trials;
      std::copy_if(data.trials.begin(),
                   data.trials.end(),
                   std::back_inserter(trials),
                   [&site](const IndentationTrial &t) {
                     return t.site == site;
                   });
      AssertThrow(!trials.empty(),
                  ExcMessage("Identification/Sites: no complete trial of "
                             "site '" +
                             site + "' in " + path + "."));
      return trials;
    }


    /// The trials of Identification/Data file at its sites, said on
    /// @p pcout; every probe face checked on every rank (a bad one found
    /// during the fit would stop one rank only).
    IndentationData
    read_trials(const IdentificationParameters &id,
                const std::string              &path,
                ConditionalOStream             &pcout)
    {
      IndentationData data = read_indentation_trials(path, id.sites);
      pcout << "Data: " << data.trials.size() << " complete trials of "
            << id.sites.size() << " site(s) in " << id.data_file;
      if (!data.incomplete_lines.empty())
        {
          pcout << "; skipped for a missing measurement: line";
          for (const unsigned int line : data.incomplete_lines)
            pcout << ' ' << line;
        }
      pcout << std::endl;
      for (const auto &trial : data.trials)
        ProbeForwardModel::check_trial(trial, id.patch_margin);
      return data;
    }


    /**
     * The subjects of @p data split once for all sites (a held-out subject
     * is held out everywhere, so that its trials at other sites can inform
     * its prediction without having been fitted); throws naming the
     * Training fraction if either part would be empty.
     */
    TrialSplit
    split_subjects(const IndentationData          &data,
                   const IdentificationParameters &id)
    {
      try
        {
          return split_by_subject(data.trials,
                                  id.training_fraction,
                                  id.split_seed);
        }
      catch (const ExceptionBase &)
        {
          // split_by_subject's own message names no parameter
          std::set<std::string> subjects;
          for (const IndentationTrial &trial : data.trials)
            subjects.insert(trial.subject);
          std::ostringstream message;
          message << "Identification/Training fraction = "
                  << id.training_fraction
                  << " leaves no training or no held-out subject among the "
                  << subjects.size()
                  << " subject(s) with trials (Identification/Sites, Data "
                     "file): the identification needs trials of at least "
                     "two subjects.";
          AssertThrow(false, ExcMessage(message.str()));
        }
      return {};
    }


    /// The trials of @p site in @p split; throws naming the site if it
    /// has no training or no held-out trial.
    TrialSplit
    split_site(const TrialSplit &split, const std::string &site)
    {
      TrialSplit site_split;
      const auto at_site = [&site](const IndentationTrial &t) {
        return t.site == site;
      };
      std::copy_if(split.training.begin(),
                   split.training.end(),
                   std::back_inserter(site_split.training),
                   at_site);
      std::copy_if(split.held_out.begin(),
                   split.held_out.end(),
                   std::back_inserter(site_split.held_out),
                   at_site);
      AssertThrow(!site_split.training.empty() && !site_split.held_out.empty(),
                  ExcMessage("The split of the subjects (Identification/"
                             "Training fraction, Split seed) leaves no " +
                             std::string(site_split.training.empty() ?
                                           "training" :
                                           "held-out") +
                             " subject with a trial at site " + site +
                             " (Identification/Sites, Data file): a site "
                             "needs trials of at least two subjects, one on "
                             "each side."));
      return site_split;
    }


    /// One site's trials and their split by subject.
    struct SiteTrials
    {
      std::vector<IndentationTrial> trials;
      TrialSplit                    split;
    };

    /// The trials of every site of @p data, each split into training and
    /// held-out subjects before the first fit starts.
    std::vector<SiteTrials>
    trials_by_site(const IndentationData          &data,
                   const IdentificationParameters &id,
                   const std::string              &path)
    {
      const TrialSplit        split = split_subjects(data, id);
      std::vector<SiteTrials> sites;
      for (const std::string &site : id.sites)
        {
          SiteTrials s;
          s.trials = site_trials(data, site, path);
          s.split  = split_site(split, site);
          sites.push_back(std::move(s));
        }
      return sites;
    }
  } // namespace


  std::array<double, 3>
  IdentificationScene::initial_moduli(const LayerModuliFit &fitter,
                                      const TrialSplit     &split,
                                      ConditionalOStream   &pcout) const
  {
    const auto fitted_layers = parameters.identification.fitted_layers();
    // start: the springs' strain moduli, scaled so that the median
    // stiffness matches (exactly so when all moduli are fitted, the model
    // being homogeneous of degree one in them)
    std::array<double, 3> initial;
    for (unsigned int l = 0; l < 3; ++l)
      initial[l] = parameters.layers.layer(l).youngs_modulus;
    const auto strain_springs =
      SpringSeriesModel::fit_to_layer_strains(split.training);
    for (unsigned int l = 0; l < 3; ++l)
      if (fitted_layers[l])
        initial[l] = strain_springs.moduli()[l];
    {
      const auto          start = fitter.predict(split.training, initial);
      std::vector<double> ratios;
      for (unsigned int t = 0; t < start.size(); ++t)
        ratios.push_back(split.training[t].surface_stiffness /
                         start[t].stiffness);
      const double scale = median(ratios);
      for (unsigned int l = 0; l < 3; ++l)
        if (fitted_layers[l])
          initial[l] *= scale;
    }
    pcout << "  start: skin " << std::setprecision(4) << initial[0] << ", fat "
          << initial[1] << ", muscle " << initial[2]
          << " MPa (springs fitted to the strains, scaled to the median "
             "stiffness)"
          << std::endl;
    return initial;
  }


  SiteFit
  IdentificationScene::fit_site(const std::string    &site,
                                const TrialSplit     &split,
                                const LayerModuliFit &fitter,
                                ConditionalOStream   &pcout) const
  {
    const IdentificationParameters &id = parameters.identification;
    SiteFit                         s;
    s.split = split;
    pcout << "Site " << site << ": " << s.split.training.size()
          << " training and " << s.split.held_out.size() << " held-out subjects"
          << std::endl;
    s.initial = initial_moduli(fitter, s.split, pcout);

    const auto fitted_layers = id.fitted_layers();
    s.fit                    = fitter.fit(s.split.training, s.initial, pcout);
    pcout << "  fitted: " << std::setprecision(4);
    for (unsigned int l = 0; l < 3; ++l)
      {
        pcout << (l > 0 ? ", " : "") << trial_layer_names[l] << ' '
              << s.fit.moduli[l];
        if (fitted_layers[l])
          pcout << " [" << s.fit.lower[l] << ", " << s.fit.upper[l] << "]";
      }
    pcout << " MPa (95 % interval); " << s.fit.stopping_reason;
    if (!parameters.run.test_mode)
      pcout << " after " << s.fit.iterations << " iterations, "
            << s.fit.forward_solves << " forward solves";
    pcout << std::endl;

    // the baseline: springs in series fitted to the training stiffnesses,
    // as Neumann et al. did; where those leave a layer's compliance
    // negative (few or unusual trials), the springs fitted to the strains
    s.baseline_model = "springs in series fitted to the training stiffnesses";
    SpringSeriesModel springs =
      SpringSeriesModel::fit_to_layer_strains(s.split.training);
    try
      {
        springs = SpringSeriesModel::fit_to_stiffness(s.split.training);
      }
    catch (const ExceptionBase &e)
      {
        s.baseline_model = "springs in series fitted to the training "
                           "strains (the stiffnesses gave a negative "
                           "compliance)";
        pcout << "  baseline: " << s.baseline_model << std::endl;
      }
    s.springs_moduli   = springs.moduli();
    s.held_out         = fitter.predict(s.split.held_out, s.fit.moduli);
    s.training         = fitter.predict(s.split.training, s.fit.moduli);
    s.held_out_springs = springs.predict(s.split.held_out);
    s.training_springs = springs.predict(s.split.training);
    return s;
  }


  void
  IdentificationScene::run()
  {
    const IdentificationParameters &id = parameters.identification;
    SceneRun            scene(parameters, mpi_communicator, "identification");
    ConditionalOStream &pcout = scene.pcout();

    const std::string path = id.data_path(parameters.file());
    const auto        trials_of_sites =
      trials_by_site(read_trials(id, path, pcout), id, path);
    const ProbeForwardModel model(parameters, scene.timer());
    const LayerModuliFit    fitter(model, id, mpi_communicator);
    IdentificationRecord    record;
    std::vector<SiteFit>    site_fits;
    for (unsigned int k = 0; k < id.sites.size(); ++k)
      {
        const std::string                   &site   = id.sites[k];
        const std::vector<IndentationTrial> &trials = trials_of_sites[k].trials;
        Timer                                site_timer;
        const SiteFit                        s =
          fit_site(site, trials_of_sites[k].split, fitter, pcout);
        record.add_site(site, s, id, pcout);
        // the size of the first trial's model, for the summary
        if (!record.has_model_size())
          {
            const ProbeResponse first =
              model.solve(trials.front(), s.fit.moduli);
            record.set_model_size(first.dofs, first.cells);
          }
        if (id.per_subject_fits)
          record.add_per_subject(
            site,
            trials,
            per_subject_fits(model, id, trials, s.fit.moduli, mpi_communicator),
            pcout);
        record.add_wall_time(site, site_timer.wall_time());
        if (!parameters.run.test_mode)
          pcout << "  " << std::setprecision(3) << site_timer.wall_time()
                << " s" << std::endl;
        site_fits.push_back(s);
      }
    pcout << "Per-person predictions (the population model's moduli times "
             "a subject factor from covariates and the subject's other "
             "sites):"
          << std::endl;
    record.add_personalised(personalised_predictions(site_fits),
                            site_fits,
                            id.sites,
                            pcout);
    record.write(scene, id);
    scene.print_wall_times();
  }


  void
  IdentificationScene::check_data(const Parameters &parameters)
  {
    const IdentificationParameters &id   = parameters.identification;
    const std::string               path = id.data_path(parameters.file());
    ConditionalOStream              quiet(std::cout, false);
    trials_by_site(read_trials(id, path, quiet), id, path);
  }
} // namespace ssc
