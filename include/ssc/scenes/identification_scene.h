#ifndef ssc_scenes_identification_scene_h
#define ssc_scenes_identification_scene_h

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
  };
} // namespace ssc

#endif
