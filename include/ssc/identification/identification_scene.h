#ifndef ssc_identification_identification_scene_h
#define ssc_identification_identification_scene_h

#include <deal.II/base/conditional_ostream.h>

#include <array>
#include <string>
#include <vector>

#include <ssc/identification/identification_record.h>
#include <ssc/identification/layer_moduli_fit.h>
#include <ssc/scenes/scene.h>

namespace ssc
{
  /**
   * The layer moduli of skin, fat and muscle identified from in vivo
   * probe indentations (the MULTIS trials, data/multis/), site by site:
   * the subjects are split into training and held-out ones; the moduli are
   * fitted to the training trials (LayerModuliFit, with the
   * ProbeForwardModel of each trial), starting from the springs-in-series
   * strain fit scaled to the measured stiffnesses; the held-out trials are
   * predicted with them, and with the springs-in-series baseline fitted to
   * the same training trials (Neumann et al. 2023).
   *
   * Writes into output/<run name>/: summary.json (`identification`:
   * moduli with 95 % confidence intervals per site; `prediction`: median
   * absolute errors on the held-out trials, the model's and the
   * baseline's), identification.csv (one row per trial: measured,
   * predicted, baseline), parameters.prm, log.txt.
   * scripts/plot_identification.py draws measured against predicted
   * stiffness.
   */
  class IdentificationScene : public Scene
  {
  public:
    using Scene::Scene;

    void
    run();

    /// Reads Identification/Data file and checks every trial and site as
    /// run() would before its first fit (ssc --check); throws naming the
    /// file, line and column or the parameter to change.
    static void
    check_data(const Parameters &parameters);

  private:
    /// The fit's start for @p split: the springs in series fitted to the
    /// training strains, scaled to the median stiffness (printed).
    std::array<double, 3>
    initial_moduli(const LayerModuliFit &fitter,
                   const TrialSplit     &split,
                   ConditionalOStream   &pcout) const;

    /// Fits the moduli to @p site's training trials of @p split and
    /// predicts every trial with them and with the springs-in-series
    /// baseline.
    SiteFit
    fit_site(const std::string    &site,
             const TrialSplit     &split,
             const LayerModuliFit &fitter,
             ConditionalOStream   &pcout) const;
  };
} // namespace ssc

#endif
