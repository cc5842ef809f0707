#ifndef ssc_identification_layer_moduli_fit_h
#define ssc_identification_layer_moduli_fit_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/mpi.h>

#include <array>
#include <string>
#include <vector>

#include <ssc/identification/indentation_trials.h>
#include <ssc/identification/prediction_errors.h>
#include <ssc/identification/probe_forward_model.h>
#include <ssc/scenes/identification_parameters.h>

namespace ssc
{
  /// Fitted layer moduli and how they were found.
  struct ModuliFit
  {
    /// Skin, fat, muscle, MPa (the fixed ones at their given values).
    std::array<double, 3> moduli{};
    /// 95 % confidence interval of each fitted modulus from the
    /// linearised least-squares covariance (the residual variance times
    /// (J^T J)^-1, in the log-moduli); NaN where not determined (as many
    /// residuals as moduli), the modulus itself where not fitted.
    std::array<double, 3> lower{}, upper{};
    unsigned int          iterations     = 0;
    unsigned int          forward_solves = 0;
    /// Root mean square of the residuals at the fit.
    double      rms_residual = 0;
    bool        converged    = false;
    std::string stopping_reason;
  };

  /**
   * Least-squares fit of the layer moduli to in vivo trials by
   * Levenberg-Marquardt (Eigen's MINPACK port) in the log-moduli, with the
   * ProbeForwardModel per trial. The residuals are, per trial and as
   * Identification/Fitted data chooses, the log of predicted over measured
   * stiffness and each layer's strain difference at the trial's largest
   * force over the trials' mean measured strain of that layer. The
   * sensitivities take two forward solves per trial beyond the model's own
   * (skin and fat moduli perturbed by 1e-3 in the log); the muscle's follow
   * from the model's homogeneity (the stiffness's log-derivatives sum to 1,
   * each strain's to -1). The trials are shared round-robin by the ranks
   * of the communicator.
   */
  class LayerModuliFit
  {
  public:
    LayerModuliFit(const ProbeForwardModel        &model,
                   const IdentificationParameters &parameters,
                   const MPI_Comm                  mpi_communicator);

    /**
     * Fits the moduli flagged in Identification/Fitted moduli to @p trials,
     * starting from @p initial (skin, fat, muscle, MPa; the others stay
     * there). Progress (one line per iteration) goes to @p pcout.
     */
    ModuliFit
    fit(const std::vector<IndentationTrial> &trials,
        const std::array<double, 3>         &initial,
        ConditionalOStream                  &pcout) const;

    /// The model's predictions for @p trials with @p moduli.
    std::vector<TrialPrediction>
    predict(const std::vector<IndentationTrial> &trials,
            const std::array<double, 3>         &moduli) const;

  private:
    const ProbeForwardModel        &model;
    const IdentificationParameters &parameters;
    MPI_Comm                        mpi_communicator;
  };

} // namespace ssc

#endif
