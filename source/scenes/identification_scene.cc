#include <deal.II/base/timer.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <limits>
#include <sstream>

#include <ssc/base/round_robin.h>
#include <ssc/identification/layer_moduli_fit.h>
#include <ssc/identification/probe_forward_model.h>
#include <ssc/identification/spring_series.h>
#include <ssc/scenes/identification_scene.h>
#include <ssc/scenes/scene_run.h>

namespace ssc
{
  namespace
  {
    nlohmann::ordered_json
    per_layer(const std::array<double, 3> &values)
    {
      nlohmann::ordered_json json;
      for (unsigned int l = 0; l < 3; ++l)
        json[trial_layer_names[l]] = values[l];
      return json;
    }

    nlohmann::ordered_json
    errors_json(const PredictionErrors &errors)
    {
      return {{"median_abs_error_stiffness_pct", errors.stiffness_pct},
              {"median_abs_error_layer_strain_pct",
               errors.pooled_layer_strain_pct},
              {"median_abs_error_strain_pct_per_layer",
               per_layer(errors.layer_strain_pct)}};
    }

    void
    print_errors(ConditionalOStream     &pcout,
                 const std::string      &what,
                 const PredictionErrors &errors)
    {
      pcout << "  " << what << ": median |error| stiffness " << std::fixed
            << std::setprecision(1) << errors.stiffness_pct
            << " %, layer strains " << errors.pooled_layer_strain_pct
            << " % (skin " << errors.layer_strain_pct[0] << ", fat "
            << errors.layer_strain_pct[1] << ", muscle "
            << errors.layer_strain_pct[2] << ")" << std::defaultfloat
            << std::endl;
    }

    /// One row of identification.csv per trial.
    void
    write_rows(std::ostream                        &csv,
               const std::string                   &set,
               const std::vector<IndentationTrial> &trials,
               const std::vector<TrialPrediction>  &model,
               const std::vector<TrialPrediction>  &springs)
    {
      for (unsigned int t = 0; t < trials.size(); ++t)
        {
          const IndentationTrial &trial = trials[t];
          csv << trial.site << ',' << trial.subject << ',' << set << ','
              << trial.line << ',' << trial.probe_area << ','
              << trial.skin_thickness << ',' << trial.fat_thickness << ','
              << trial.muscle_thickness << ',' << trial.max_force << ','
              << trial.surface_stiffness << ',' << model[t].stiffness << ','
              << springs[t].stiffness;
          for (const auto &strains : {trial.layer_strains(),
                                      model[t].layer_strains,
                                      springs[t].layer_strains})
            for (const double e : strains)
              csv << ',' << e;
          csv << '\n';
        }
    }

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


    /// Median and quartiles of each layer's converged per-subject moduli.
    nlohmann::ordered_json
    per_subject_summary(const std::vector<std::array<double, 4>> &rows)
    {
      nlohmann::ordered_json json;
      unsigned int           converged = 0;
      for (const auto &row : rows)
        converged += row[3] > 0.5;
      json["subjects"]  = rows.size();
      json["converged"] = converged;
      for (unsigned int l = 0; l < 3; ++l)
        {
          std::vector<double> values;
          for (const auto &row : rows)
            if (row[3] > 0.5)
              values.push_back(row[l]);
          if (values.empty())
            continue;
          std::sort(values.begin(), values.end());
          const auto at = [&values](const double q) {
            return values[std::lround(q * (values.size() - 1))];
          };
          json[std::string(trial_layer_names[l]) + "_MPa"] = {
            {"median", median(values)},
            {"quartile_1", at(0.25)},
            {"quartile_3", at(0.75)}};
        }
      return json;
    }
  } // namespace


  void
  IdentificationScene::run()
  {
    const IdentificationParameters &id = parameters.identification;
    SceneRun            scene(parameters, mpi_communicator, "identification");
    ConditionalOStream &pcout   = scene.pcout();
    const bool          verbose = !parameters.run.test_mode;

    const std::string     path = id.data_path(parameters.file());
    const IndentationData data = read_indentation_trials(path, id.sites);
    pcout << "Data: " << data.trials.size() << " complete trials of "
          << id.sites.size() << " site(s) in " << id.data_file;
    if (!data.incomplete_lines.empty())
      {
        pcout << "; skipped for a missing measurement: line";
        for (const unsigned int line : data.incomplete_lines)
          pcout << ' ' << line;
      }
    pcout << std::endl;
    // every rank checks every trial's probe face now: a bad one found
    // during the fit would stop one rank only
    for (const auto &trial : data.trials)
      ProbeForwardModel::probe_face(trial);

    const ProbeForwardModel model(parameters, scene.timer());
    const LayerModuliFit    fitter(model, id, mpi_communicator);
    const auto              fitted_layers = id.fitted_layers();
    std::array<double, 3>   stack_moduli;
    for (unsigned int l = 0; l < 3; ++l)
      stack_moduli[l] = parameters.layers.layer(l).youngs_modulus;

    nlohmann::ordered_json identification, per_site;
    // every site's held-out trials, for the pooled errors
    std::vector<IndentationTrial> all_held_out;
    std::vector<TrialPrediction>  all_model, all_springs;
    std::ostringstream            csv;
    csv << "site,subject,set,line,probe_area_mm2,skin_mm,fat_mm,muscle_mm,"
           "max_force_N,stiffness_measured_N_per_mm,stiffness_model,"
           "stiffness_springs,skin_strain_measured,fat_strain_measured,"
           "muscle_strain_measured,skin_strain_model,fat_strain_model,"
           "muscle_strain_model,skin_strain_springs,fat_strain_springs,"
           "muscle_strain_springs\n"
        << std::setprecision(8);
    std::ostringstream subject_csv;
    subject_csv << "site,subject,skin_MPa,fat_MPa,muscle_MPa,converged\n"
                << std::setprecision(8);
    unsigned int dofs = 0, cells = 0;

    for (const std::string &site : id.sites)
      {
        Timer                         site_timer;
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
        const TrialSplit split =
          split_by_subject(trials, id.training_fraction, id.split_seed);
        AssertThrow(!split.training.empty() && !split.held_out.empty(),
                    ExcMessage(
                      "Identification/Training fraction = " +
                      std::to_string(id.training_fraction) + " leaves no " +
                      (split.training.empty() ? "training" : "held-out") +
                      " subject among the " + std::to_string(trials.size()) +
                      " of " + site + "."));
        pcout << "Site " << site << ": " << split.training.size()
              << " training and " << split.held_out.size()
              << " held-out subjects" << std::endl;

        // start: the springs' strain moduli, scaled so that the median
        // stiffness matches (exactly so when all moduli are fitted, the
        // model being homogeneous of degree one in them)
        std::array<double, 3> initial = stack_moduli;
        const auto            strain_springs =
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
        pcout << "  start: skin " << std::setprecision(4) << initial[0]
              << ", fat " << initial[1] << ", muscle " << initial[2]
              << " MPa (springs fitted to the strains, scaled to the median "
                 "stiffness)"
              << std::endl;

        const ModuliFit fit = fitter.fit(split.training, initial, pcout);
        pcout << "  fitted: " << std::setprecision(4);
        for (unsigned int l = 0; l < 3; ++l)
          {
            pcout << (l > 0 ? ", " : "") << trial_layer_names[l] << ' '
                  << fit.moduli[l];
            if (fitted_layers[l])
              pcout << " [" << fit.lower[l] << ", " << fit.upper[l] << "]";
          }
        pcout << " MPa (95 % interval); " << fit.stopping_reason;
        if (verbose)
          pcout << " after " << fit.iterations << " iterations, "
                << fit.forward_solves << " forward solves";
        pcout << std::endl;

        // the baseline: springs in series fitted to the training
        // stiffnesses, as Neumann et al. did; where those leave a layer's
        // compliance negative (few or unusual trials), the springs fitted
        // to the strains
        std::string       baseline_model = "springs in series fitted to the "
                                           "training stiffnesses";
        SpringSeriesModel springs        = strain_springs;
        try
          {
            springs = SpringSeriesModel::fit_to_stiffness(split.training);
          }
        catch (const ExceptionBase &e)
          {
            baseline_model = "springs in series fitted to the training "
                             "strains (the stiffnesses gave a negative "
                             "compliance)";
            pcout << "  baseline: " << baseline_model << std::endl;
          }
        const auto held_out = fitter.predict(split.held_out, fit.moduli);
        const auto training = fitter.predict(split.training, fit.moduli);
        const auto held_out_springs = springs.predict(split.held_out);
        const auto training_springs = springs.predict(split.training);
        const PredictionErrors errors =
          prediction_errors(held_out, split.held_out);
        const PredictionErrors baseline =
          prediction_errors(held_out_springs, split.held_out);
        print_errors(pcout, "held out, model  ", errors);
        print_errors(pcout, "held out, springs", baseline);
        write_rows(csv, "training", split.training, training, training_springs);
        write_rows(csv, "held_out", split.held_out, held_out, held_out_springs);
        // the size of the first trial's model, for the summary
        if (dofs == 0)
          {
            const ProbeResponse first = model.solve(trials.front(), fit.moduli);
            dofs                      = first.dofs;
            cells                     = first.cells;
          }

        nlohmann::ordered_json site_fit = {
          {"training_subjects", split.training.size()},
          {"held_out_subjects", split.held_out.size()},
          {"moduli_MPa", per_layer(fit.moduli)},
          {"ci95_lower_MPa", per_layer(fit.lower)},
          {"ci95_upper_MPa", per_layer(fit.upper)},
          {"initial_moduli_MPa", per_layer(initial)},
          {"fitted_moduli", id.fitted_moduli},
          {"fitted_data", id.fitted_data},
          {"rms_residual", fit.rms_residual},
          {"converged", fit.converged},
          {"stopping_reason", fit.stopping_reason},
          {"iterations", fit.iterations},
          {"forward_solves", fit.forward_solves},
          {"springs_moduli_MPa", per_layer(springs.moduli())}};
        identification[site] = site_fit;
        all_held_out.insert(all_held_out.end(),
                            split.held_out.begin(),
                            split.held_out.end());
        all_model.insert(all_model.end(), held_out.begin(), held_out.end());
        all_springs.insert(all_springs.end(),
                           held_out_springs.begin(),
                           held_out_springs.end());
        per_site[site] = errors_json(errors);
        per_site[site]["training"] =
          errors_json(prediction_errors(training, split.training));
        per_site[site]["baseline"]          = errors_json(baseline);
        per_site[site]["baseline"]["model"] = baseline_model;
        if (id.per_subject_fits)
          {
            const auto rows =
              per_subject_fits(model, id, trials, fit.moduli, mpi_communicator);
            for (unsigned int t = 0; t < trials.size(); ++t)
              {
                subject_csv << site << ',' << trials[t].subject;
                for (const double value : rows[t])
                  subject_csv << ',' << value;
                subject_csv << '\n';
              }
            identification[site]["per_subject"] = per_subject_summary(rows);
            pcout << "  per-subject fits: "
                  << identification[site]["per_subject"]["converged"] << " of "
                  << trials.size() << " converged" << std::endl;
          }
        identification[site]["wall_time_s"] = site_timer.wall_time();
        if (verbose)
          pcout << "  " << std::setprecision(3) << site_timer.wall_time()
                << " s" << std::endl;
      }

    scene.output().write_text("identification.csv", csv.str());
    if (id.per_subject_fits)
      scene.output().write_text("per_subject_moduli.csv", subject_csv.str());
    nlohmann::ordered_json summary = scene.summary(dofs, cells);
    summary["data_file"]           = id.data_file;
    summary["training_fraction"]   = id.training_fraction;
    summary["split_seed"]          = id.split_seed;
    summary["identification"]      = identification;
    // the held-out trials of all sites together, then per site
    nlohmann::ordered_json prediction =
      errors_json(prediction_errors(all_model, all_held_out));
    prediction["held_out_trials"] = all_held_out.size();
    prediction["baseline"] =
      errors_json(prediction_errors(all_springs, all_held_out));
    prediction["per_site"] = per_site;
    summary["prediction"]  = prediction;
    scene.output().write_summary(summary);
    scene.print_wall_times();
  }
} // namespace ssc
