#include <algorithm>
#include <cmath>
#include <iomanip>

#include <ssc/identification/identification_record.h>
#include <ssc/identification/personalised_predictions.h>

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
      // formatted apart: the stream's precision stays the caller's
      std::ostringstream line;
      line << "  " << what << ": median |error| stiffness " << std::fixed
           << std::setprecision(1) << errors.stiffness_pct
           << " %, layer strains " << errors.pooled_layer_strain_pct
           << " % (skin " << errors.layer_strain_pct[0] << ", fat "
           << errors.layer_strain_pct[1] << ", muscle "
           << errors.layer_strain_pct[2] << ")";
      pcout << line.str() << std::endl;
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


  IdentificationRecord::IdentificationRecord()
  {
    csv << "site,subject,set,line,probe_area_mm2,skin_mm,fat_mm,muscle_mm,"
           "max_force_N,stiffness_measured_N_per_mm,stiffness_model,"
           "stiffness_springs,skin_strain_measured,fat_strain_measured,"
           "muscle_strain_measured,skin_strain_model,fat_strain_model,"
           "muscle_strain_model,skin_strain_springs,fat_strain_springs,"
           "muscle_strain_springs\n"
        << std::setprecision(8);
    subject_csv << "site,subject,skin_MPa,fat_MPa,muscle_MPa,converged\n"
                << std::setprecision(8);
    person_csv << std::setprecision(8);
  }


  void
  IdentificationRecord::add_site(const std::string              &site,
                                 const SiteFit                  &s,
                                 const IdentificationParameters &id,
                                 ConditionalOStream             &pcout)
  {
    const PredictionErrors errors =
      prediction_errors(s.held_out, s.split.held_out);
    const PredictionErrors baseline =
      prediction_errors(s.held_out_springs, s.split.held_out);
    print_errors(pcout, "held out, model  ", errors);
    print_errors(pcout, "held out, springs", baseline);
    write_rows(
      csv, "training", s.split.training, s.training, s.training_springs);
    write_rows(
      csv, "held_out", s.split.held_out, s.held_out, s.held_out_springs);

    identification[site] = {{"training_subjects", s.split.training.size()},
                            {"held_out_subjects", s.split.held_out.size()},
                            {"moduli_MPa", per_layer(s.fit.moduli)},
                            {"ci95_lower_MPa", per_layer(s.fit.lower)},
                            {"ci95_upper_MPa", per_layer(s.fit.upper)},
                            {"initial_moduli_MPa", per_layer(s.initial)},
                            {"fitted_moduli", id.fitted_moduli},
                            {"fitted_data", id.fitted_data},
                            {"rms_residual", s.fit.rms_residual},
                            {"converged", s.fit.converged},
                            {"stopping_reason", s.fit.stopping_reason},
                            {"iterations", s.fit.iterations},
                            {"forward_solves", s.fit.forward_solves},
                            {"springs_moduli_MPa",
                             per_layer(s.springs_moduli)}};
    all_held_out.insert(all_held_out.end(),
                        s.split.held_out.begin(),
                        s.split.held_out.end());
    all_model.insert(all_model.end(), s.held_out.begin(), s.held_out.end());
    all_springs.insert(all_springs.end(),
                       s.held_out_springs.begin(),
                       s.held_out_springs.end());
    per_site[site] = errors_json(errors);
    per_site[site]["training"] =
      errors_json(prediction_errors(s.training, s.split.training));
    per_site[site]["baseline"]          = errors_json(baseline);
    per_site[site]["baseline"]["model"] = s.baseline_model;
  }


  void
  IdentificationRecord::add_per_subject(
    const std::string                        &site,
    const std::vector<IndentationTrial>      &trials,
    const std::vector<std::array<double, 4>> &rows,
    ConditionalOStream                       &pcout)
  {
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


  void
  IdentificationRecord::add_personalised(
    const std::vector<PersonalisedPredictions> &methods,
    const std::vector<SiteFit>                 &sites,
    const std::vector<std::string>             &site_names,
    ConditionalOStream                         &pcout)
  {
    person_csv << "site,subject,set,stiffness_measured_N_per_mm,"
                  "stiffness_model,stiffness_springs";
    std::vector<const PersonalisedPredictions *> determined;
    for (const PersonalisedPredictions &method : methods)
      if (method.not_determined.empty())
        {
          determined.push_back(&method);
          person_csv << ",stiffness_"
                     << subject_information_key(method.information);
        }
    person_csv << '\n';
    for (unsigned int k = 0; k < sites.size(); ++k)
      for (const bool held_out : {false, true})
        {
          const SiteFit &s   = sites[k];
          const auto &trials = held_out ? s.split.held_out : s.split.training;
          for (unsigned int t = 0; t < trials.size(); ++t)
            {
              person_csv << site_names[k] << ',' << trials[t].subject << ','
                         << (held_out ? "held_out" : "training") << ','
                         << trials[t].surface_stiffness << ','
                         << (held_out ? s.held_out : s.training)[t].stiffness
                         << ','
                         << (held_out ? s.held_out_springs :
                                        s.training_springs)[t]
                              .stiffness;
              for (const PersonalisedPredictions *method : determined)
                person_csv << ','
                           << (held_out ? method->held_out :
                                          method->training)[k][t]
                                .stiffness;
              person_csv << '\n';
            }
        }

    for (const PersonalisedPredictions &method : methods)
      {
        const std::string key = subject_information_key(method.information);
        if (!method.not_determined.empty())
          {
            personalised[key] = {{"not_determined", method.not_determined}};
            pcout << "  " << key
                  << ": not determined: " << method.not_determined << std::endl;
            continue;
          }
        std::vector<IndentationTrial> trials;
        std::vector<TrialPrediction>  predictions;
        nlohmann::ordered_json        by_site;
        for (unsigned int k = 0; k < sites.size(); ++k)
          {
            const auto &held_out = sites[k].split.held_out;
            trials.insert(trials.end(), held_out.begin(), held_out.end());
            predictions.insert(predictions.end(),
                               method.held_out[k].begin(),
                               method.held_out[k].end());
            const PredictionErrors errors =
              prediction_errors(method.held_out[k], held_out);
            nlohmann::ordered_json site = errors_json(errors);
            site["training"]            = errors_json(
              prediction_errors(method.training[k], sites[k].split.training));
            site["r_squared"] = method.models[k].r_squared();
            // each coefficient as the factor on the moduli per unit of its
            // feature, exp(beta)
            for (const FactorCoefficient &c : method.models[k].coefficients())
              site["moduli_factor"][c.name] = {
                {"value", std::exp(c.value)},
                {"ci95_lower", std::exp(c.lower)},
                {"ci95_upper", std::exp(c.upper)}};
            by_site[site_names[k]] = site;
            print_errors(pcout, site_names[k] + " held out, " + key, errors);
          }
        personalised[key] = errors_json(prediction_errors(predictions, trials));
        personalised[key]["per_site"] = by_site;
      }

    // the ceiling of any per-person method that uses other sites
    if (personalised.contains("cross_site") &&
        !personalised["cross_site"].contains("not_determined"))
      {
        const auto r = site_correlations(sites);
        for (unsigned int a = 0; a < sites.size(); ++a)
          for (unsigned int b = 0; b < sites.size(); ++b)
            if (a != b)
              personalised["cross_site"]["site_correlation"][site_names[a]]
                          [site_names[b]] = std::isfinite(r[a][b]) ?
                                              nlohmann::ordered_json(r[a][b]) :
                                              nlohmann::ordered_json();
      }
  }


  void
  IdentificationRecord::add_wall_time(const std::string &site,
                                      const double       seconds)
  {
    identification[site]["wall_time_s"] = seconds;
  }


  void
  IdentificationRecord::set_model_size(const unsigned int model_dofs,
                                       const unsigned int model_cells)
  {
    dofs  = model_dofs;
    cells = model_cells;
  }


  void
  IdentificationRecord::write(SceneRun                       &scene,
                              const IdentificationParameters &id) const
  {
    scene.output().write_text("identification.csv", csv.str());
    if (id.per_subject_fits)
      scene.output().write_text("per_subject_moduli.csv", subject_csv.str());
    if (!personalised.empty())
      scene.output().write_text("person_predictions.csv", person_csv.str());
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
    for (const auto &[key, value] : personalised.items())
      prediction[key] = value;
    summary["prediction"] = prediction;
    scene.output().write_summary(summary);
  }
} // namespace ssc
