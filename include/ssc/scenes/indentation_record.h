#ifndef ssc_scenes_indentation_record_h
#define ssc_scenes_indentation_record_h

#include <deal.II/base/conditional_ostream.h>

#include <nlohmann/json.hpp>

#include <vector>

#include <ssc/contact/contact_log.h>
#include <ssc/embedding/point_locator.h>
#include <ssc/output/run_output.h>
#include <ssc/scenes/indentation_output.h>
#include <ssc/scenes/mechanics_model.h>
#include <ssc/scenes/parameters.h>
#include <ssc/scenes/punch_loading.h>
#include <ssc/scenes/quasi_static_driver.h>

namespace ssc
{
  /// What the indentation scene measured.
  struct IndentationResult
  {
    types::global_dof_index dofs = 0;
    std::vector<double>     depths; ///< mm, per load step
    std::vector<double>     forces; ///< N, per load step
    double                  stiffness            = 0;
    double                  half_space_stiffness = 0;
    /// Each layer's compressive strain under the punch centre, per load
    /// step (outer) and layer from the top (inner).
    std::vector<std::vector<double>> layer_strains;
    /// The estimated discretisation error of the depth (richer minus this
    /// discretisation, mm) per load step; empty without an estimate.
    std::vector<double> depth_error_estimates;
  };


  /**
   * The indentation scene's record: what each load step measured (force,
   * depth, each layer's strain under the punch centre as an ultrasound image
   * measures it, the surface profile, the edge contact and friction through
   * their own logs), the progress line of each step, and from them the
   * scene's tables and its part of summary.json. The scene only says when a
   * step is reached.
   */
  class IndentationRecord
  {
  public:
    IndentationRecord(const Parameters        &parameters,
                      MechanicsModel          &model,
                      PunchLoading            &loading,
                      const QuasiStaticDriver &driver,
                      ConditionalOStream      &pcout);

    /// Measures load step @p step (its load @p load reached); prints the
    /// unit load's response (linear problems) and the contact and friction
    /// state.
    void
    record(const unsigned int step, const double load);

    /// Records the estimated error of the last recorded step's depth,
    /// @p depth_change (mm, a richer discretisation's depth minus this
    /// one's), by @p method on @p dofs DoFs.
    void
    record_depth_error(const double                  depth_change,
                       const std::string            &method,
                       const types::global_dof_index dofs);

    /// The force (N) of the last recorded step.
    double
    last_force() const
    {
      return result.forces.back();
    }

    /// The depth (mm) of the last recorded step.
    double
    last_depth() const
    {
      return result.depths.back();
    }

    /// The progress line of the last recorded step.
    void
    print_step(const unsigned int step, const unsigned int n_steps) const;

    /// Writes the section (and the septa's), the surface profile and the
    /// force-displacement table into @p output, and prints the stiffness.
    void
    write_tables(const std::vector<double> &loads, RunOutput &output);

    /// Adds the scene's results to @p summary (the keys of
    /// docs/architecture.md) and returns them.
    IndentationResult
    add_to_summary(nlohmann::ordered_json &summary) const;

  private:
    const Parameters                &parameters;
    MechanicsModel                  &model;
    PunchLoading                    &loading;
    const QuasiStaticDriver         &driver;
    ConditionalOStream              &pcout;
    const PointLocator               locator;
    const std::vector<Point<3>>      profile_at;
    const std::vector<PointLocation> profile_locations;
    const CentreAxisStrains          centre_axis;
    IndentationResult                result;
    std::vector<std::vector<double>> profiles;
    EdgeContactLog                   contact_log;
    FrictionLog                      friction_log;
    /// |reaction - 1 N| of the tied punch under the unit force (linear)
    double tie_balance = 0;
    /// how the depth's error was estimated and on how many DoFs
    std::string             depth_error_method;
    types::global_dof_index depth_error_dofs = 0;
  };
} // namespace ssc

#endif
