#ifndef ssc_identification_probe_forward_model_h
#define ssc_identification_probe_forward_model_h

#include <deal.II/base/timer.h>

#include <array>
#include <string>
#include <utility>
#include <vector>

#include <ssc/identification/indentation_trials.h>
#include <ssc/scenes/parameters.h>

namespace ssc
{
  /// The forward model's answer for one trial and one set of moduli.
  struct ProbeResponse
  {
    /// Force over the probe's depth, N/mm.
    double stiffness = 0;
    /// Skin, fat and muscle compressive strain under the probe centre per
    /// newton of probe force, 1/N.
    std::array<double, 3> strains_per_newton{};
    /// Size of the trial's model.
    unsigned int dofs  = 0;
    unsigned int cells = 0;
  };

  /**
   * One in vivo trial as a finite-element problem: the trial's skin, fat
   * and muscle thicknesses over a rigid bone (the patch's fixed bottom),
   * pressed by the trial's flat probe face with a unit force. The mesh,
   * degree, formulation, contact and Poisson's ratios are the run's own
   * (its Layer stack, Mesh, Elasticity and Punch sections); per trial the
   * parameter file is read again with overrides for the thicknesses, the
   * moduli, the probe face and a patch that reaches Identification/Patch
   * margin tissue thicknesses beyond the probe on each side, its mesh core
   * the probe's face. The layers are linear (small strain): the response
   * to any force is the unit force's scaled, and it is homogeneous of
   * degree one in the moduli (all scaled by c: stiffness times c, strains
   * over c).
   */
  class ProbeForwardModel
  {
  public:
    /// @p parameters: the identification run's; @p timer times the phases
    /// (mesh, setup, assembly, solve) of every forward solve.
    ProbeForwardModel(const Parameters &parameters, TimerOutput &timer);

    /// The response of @p trial's stack with layer @p moduli (skin, fat,
    /// muscle, MPa), computed on this process alone (MPI_COMM_SELF).
    ProbeResponse
    solve(const IndentationTrial      &trial,
          const std::array<double, 3> &moduli) const;

    /**
     * The probe face (length, width in mm) of a trial, from its area:
     * the MULTIS study's two transducers, 14L5 (45 x 8 mm = 360 mm^2) and
     * 9L4 (45 x 15 mm = 675 mm^2) (data/multis/README.md). Throws, naming
     * the data line, for an area that is neither.
     */
    static std::pair<double, double>
    probe_face(const IndentationTrial &trial);

    /**
     * Throws, naming the data line and Identification/Patch margin, unless
     * @p trial has a known probe face and a patch of @p patch_margin tissue
     * thicknesses beyond it stays within MeshParameters::max_patch_length
     * (checked before the first fit; the model would otherwise blame the
     * Mesh/Patch length it was given).
     */
    static void
    check_trial(const IndentationTrial &trial, double patch_margin);

  private:
    /// The overrides that make the run's parameter file @p trial's model.
    std::vector<std::string>
    overrides(const IndentationTrial      &trial,
              const std::array<double, 3> &moduli) const;

    const Parameters &parameters;
    TimerOutput      &timer;
  };
} // namespace ssc

#endif
