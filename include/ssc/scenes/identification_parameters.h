#ifndef ssc_scenes_identification_parameters_h
#define ssc_scenes_identification_parameters_h

#include <deal.II/base/parameter_handler.h>

#include <array>
#include <string>
#include <vector>

namespace ssc
{
  using namespace dealii;

  /// The layers of a trial, from the top, as the data and the
  /// identification name them.
  inline constexpr std::array<const char *, 3> trial_layer_names{
    {"skin", "fat", "muscle"}};

  /**
   * Section "Identification": which in vivo trials the layer moduli are
   * fitted to (data file, sites, the subjects held out), which moduli and
   * which measurements enter the fit, and how the forward model's patch is
   * sized from each trial. The forward model itself (mesh, degree, contact,
   * Poisson's ratios) is the prm file's Layer stack, Mesh, Elasticity and
   * Punch sections.
   */
  struct IdentificationParameters
  {
    /// The MULTIS per-trial table; a relative path is taken from the
    /// folder of the parameter file.
    std::string              data_file = "";
    std::vector<std::string> sites     = {"LA_A", "LA_P", "UA_A", "UA_P"};
    double                   training_fraction = 0.75;
    unsigned int             split_seed        = 1;
    std::vector<std::string> fitted_moduli     = {"skin", "fat", "muscle"};
    std::vector<std::string> fitted_data       = {"stiffness",
                                                  "fat strain",
                                                  "muscle strain"};
    /// The patch reaches this many total tissue thicknesses beyond each
    /// side of the probe.
    double       patch_margin       = 3;
    unsigned int maximum_iterations = 40;
    double       tolerance          = 1e-4;
    bool         per_subject_fits   = false;

    /// Declares section "Identification", bound to the members.
    void
    add_parameters(ParameterHandler &prm);

    /// Checks the values (after parsing); throws naming the parameter.
    void
    check() const;

    /// Whether the modulus of layer @p layer (0 skin, 1 fat, 2 muscle) is
    /// fitted (else it stays at its Layer stack value).
    std::array<bool, 3>
    fitted_layers() const;

    /// Which measurements enter the fit: stiffness, then the skin, fat and
    /// muscle strains.
    std::array<bool, 4>
    fitted_measurements() const;

    /// The data file as a path: relative ones from @p parameter_file's
    /// folder.
    std::string
    data_path(const std::string &parameter_file) const;
  };
} // namespace ssc

#endif
