#include <deal.II/base/exceptions.h>

#include <algorithm>
#include <filesystem>

#include <ssc/scenes/identification_parameters.h>

namespace ssc
{
  namespace
  {
    const std::array<const char *, 4> measurement_names{
      {"stiffness", "skin strain", "fat strain", "muscle strain"}};

    template <std::size_t n>
    std::array<bool, n>
    mask(const std::vector<std::string>    &chosen,
         const std::array<const char *, n> &names)
    {
      std::array<bool, n> on{};
      for (unsigned int i = 0; i < n; ++i)
        on[i] =
          std::find(chosen.begin(), chosen.end(), names[i]) != chosen.end();
      return on;
    }
  } // namespace


  void
  IdentificationParameters::add_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Identification");
    prm.add_parameter(
      "Data file",
      data_file,
      "The in vivo indentation trials (the MULTIS per-trial table, "
      "data/multis/README.md). A relative path is taken from the folder of "
      "the parameter file.",
      Patterns::Anything());
    prm.add_parameter("Sites",
                      sites,
                      "Sites fitted one after the other, each on its own "
                      "(site codes of the data's Location column: LA_A, "
                      "LA_P, UA_A, UA_P, LL_A, LL_P, UL_A, UL_P).",
                      Patterns::List(Patterns::Anything(), 1));
    prm.add_parameter("Training fraction",
                      training_fraction,
                      "Share of the subjects whose trials the moduli are "
                      "fitted to; the others are held out and predicted.",
                      Patterns::Double(0, 1));
    prm.add_parameter("Split seed",
                      split_seed,
                      "Seed of the shuffle that splits the subjects into "
                      "training and held-out ones.",
                      Patterns::Integer(0));
    prm.add_parameter("Fitted moduli",
                      fitted_moduli,
                      "Layers whose Young's modulus is fitted; the others "
                      "keep their Layer stack value.",
                      Patterns::List(Patterns::Selection("skin|fat|muscle"),
                                     1,
                                     3));
    prm.add_parameter(
      "Fitted data",
      fitted_data,
      "Measurements the fit matches: the surface stiffness (as the log of "
      "predicted over measured) and each layer's compressive strain at the "
      "trial's largest force (the difference over the training trials' mean "
      "of that strain).",
      Patterns::List(Patterns::Selection(
                       "stiffness|skin strain|fat strain|muscle strain"),
                     1,
                     4));
    prm.add_parameter("Patch margin",
                      patch_margin,
                      "The forward model's patch reaches this many times the "
                      "trial's tissue thickness (skin surface to bone) "
                      "beyond each side of the probe; its sides are held by "
                      "Elasticity/Sides (3: the stiffness within 0.04 % of a "
                      "patch half as large again).",
                      Patterns::Double(0));
    prm.add_parameter("Maximum iterations",
                      maximum_iterations,
                      "Levenberg-Marquardt iterations of one fit at most.",
                      Patterns::Integer(1, 1000));
    prm.add_parameter("Tolerance",
                      tolerance,
                      "The fit stops when a step changes the log-moduli or "
                      "the sum of squares by less than this (relative).",
                      Patterns::Double(0));
    prm.add_parameter("Per-subject fits",
                      per_subject_fits,
                      "Also fit every subject's moduli to that subject's "
                      "own trial (costly: a full fit per subject).");
    prm.leave_subsection();
  }


  void
  IdentificationParameters::check() const
  {
    AssertThrow(training_fraction > 0 && training_fraction < 1,
                ExcMessage("Identification/Training fraction must lie "
                           "strictly between 0 and 1 (some subjects are "
                           "fitted, some held out), not " +
                           std::to_string(training_fraction) + "."));
    AssertThrow(tolerance > 0,
                ExcMessage("Identification/Tolerance must be positive."));
    AssertThrow(patch_margin >= 0.5,
                ExcMessage("Identification/Patch margin = " +
                           std::to_string(patch_margin) +
                           " is below 0.5 tissue thicknesses: the patch's "
                           "sides would hold the tissue under the probe."));
    for (auto site = sites.begin(); site != sites.end(); ++site)
      AssertThrow(std::find(site + 1, sites.end(), *site) == sites.end(),
                  ExcMessage("Identification/Sites names " + *site +
                             " twice: each site is fitted once."));
    const auto fitted = fitted_measurements();
    const auto layers = fitted_layers();
    AssertThrow(std::count(fitted.begin(), fitted.end(), true) >=
                  std::count(layers.begin(), layers.end(), true),
                ExcMessage("Identification: fewer kinds of Fitted data than "
                           "Fitted moduli; the moduli would not be "
                           "determined."));
  }


  std::array<bool, 3>
  IdentificationParameters::fitted_layers() const
  {
    return mask(fitted_moduli, trial_layer_names);
  }


  std::array<bool, 4>
  IdentificationParameters::fitted_measurements() const
  {
    return mask(fitted_data, measurement_names);
  }


  std::string
  IdentificationParameters::data_path(const std::string &parameter_file) const
  {
    const std::filesystem::path path(data_file);
    if (path.is_absolute() || parameter_file.empty())
      return path.string();
    return (std::filesystem::path(parameter_file).parent_path() / path)
      .lexically_normal()
      .string();
  }
} // namespace ssc
