// The springs-in-series baseline of the in vivo identification:
// - on synthetic trials made by the model itself (the shipped forearm
//   trials' thicknesses, probe areas and forces, with stiffness and layer
//   strains from known moduli) the fit recovers the moduli to 1e-10 and
//   the prediction errors vanish;
// - the split by subject is deterministic for a seed, keeps each
//   subject's trials together and differs between seeds;
// - on the four arm sites (seed 1, 80 % of the subjects for training):
//   the fitted apparent moduli and the held-out median errors.

#include <algorithm>
#include <set>

#include <ssc/identification/spring_series.h>

#include "tests.h"

using namespace dealii;

namespace
{
  const std::string data_file =
    SOURCE_DIR "/../data/multis/indentation_trials.csv";

  std::set<std::string>
  subjects(const std::vector<ssc::IndentationTrial> &trials)
  {
    std::set<std::string> result;
    for (const auto &trial : trials)
      result.insert(trial.subject);
    return result;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();

  const auto forearm = ssc::read_indentation_trials(data_file, {"LA_A"}).trials;
  const ssc::SpringSeriesModel truth(std::array<double, 3>{{0.05, 0.02, 0.03}});
  std::vector<ssc::IndentationTrial> synthetic = forearm;
  for (auto &trial : synthetic)
    {
      trial.surface_stiffness = truth.stiffness(trial);
      const auto strains      = truth.layer_strains(trial);
      trial.skin_strain       = strains[0];
      trial.fat_strain        = strains[1];
      trial.muscle_strain     = strains[2];
    }
  const auto fitted = ssc::SpringSeriesModel::fit_to_stiffness(synthetic);
  const auto by_strain =
    ssc::SpringSeriesModel::fit_to_layer_strains(synthetic);
  double max_error = 0;
  for (unsigned int i = 0; i < 3; ++i)
    max_error =
      std::max({max_error,
                std::abs(fitted.moduli()[i] / truth.moduli()[i] - 1),
                std::abs(by_strain.moduli()[i] / truth.moduli()[i] - 1)});
  deallog << "synthetic: " << synthetic.size()
          << " trials, largest relative modulus error (both fits) "
          << (max_error < 1e-10 ? "below 1e-10" : "TOO LARGE") << std::endl;
  const auto exact = ssc::prediction_errors(fitted, synthetic);
  deallog << "synthetic: prediction errors "
          << (exact.stiffness_pct < 1e-8 &&
                  exact.pooled_layer_strain_pct < 1e-8 ?
                "below 1e-8 %" :
                "TOO LARGE")
          << std::endl;

  const auto            split = ssc::split_by_subject(forearm, 0.8, 1);
  const auto            again = ssc::split_by_subject(forearm, 0.8, 1);
  const auto            other = ssc::split_by_subject(forearm, 0.8, 2);
  std::set<std::string> shared;
  for (const auto &s : subjects(split.training))
    if (subjects(split.held_out).count(s))
      shared.insert(s);
  deallog << "split: " << subjects(split.training).size() << " + "
          << subjects(split.held_out).size() << " subjects, "
          << split.training.size() << " + " << split.held_out.size()
          << " trials, subjects on both sides: " << shared.size()
          << ", same for the same seed: "
          << (subjects(again.held_out) == subjects(split.held_out) ? "yes" :
                                                                     "no")
          << ", same for seed 2: "
          << (subjects(other.held_out) == subjects(split.held_out) ? "yes" :
                                                                     "no")
          << std::endl;

  for (const std::string site : {"LA_A", "LA_P", "UA_A", "UA_P"})
    {
      const auto trials = ssc::read_indentation_trials(data_file, {site});
      const auto parts  = ssc::split_by_subject(trials.trials, 0.8, 1);
      for (const bool by_stiffness : {true, false})
        {
          const auto model =
            by_stiffness ?
              ssc::SpringSeriesModel::fit_to_stiffness(parts.training) :
              ssc::SpringSeriesModel::fit_to_layer_strains(parts.training);
          const auto errors = ssc::prediction_errors(model, parts.held_out);
          deallog << std::setprecision(3) << site << ", fit to "
                  << (by_stiffness ? "stiffness" : "layer strains")
                  << ": E (kPa) skin " << 1e3 * model.moduli()[0] << ", fat "
                  << 1e3 * model.moduli()[1] << ", muscle "
                  << 1e3 * model.moduli()[2] << "; held out ("
                  << parts.held_out.size()
                  << " trials): median |error| stiffness "
                  << errors.stiffness_pct << " %, strain skin "
                  << errors.layer_strain_pct[0] << " %, fat "
                  << errors.layer_strain_pct[1] << " %, muscle "
                  << errors.layer_strain_pct[2] << " %, pooled "
                  << errors.pooled_layer_strain_pct << " %" << std::endl;
        }
    }
}
