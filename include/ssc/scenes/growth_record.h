#ifndef ssc_scenes_growth_record_h
#define ssc_scenes_growth_record_h

#include <deal.II/base/conditional_ostream.h>

#include <nlohmann/json.hpp>

#include <vector>

#include <ssc/embedding/point_locator.h>
#include <ssc/output/run_output.h>
#include <ssc/scenes/mechanics_model.h>
#include <ssc/scenes/parameters.h>
#include <ssc/scenes/quasi_static_driver.h>
#include <ssc/scenes/surface_metrics.h>

namespace ssc
{
  /// What the growth scene measured, per load step.
  struct GrowthResult
  {
    double                      growth_ratio    = 0; ///< g
    double                      selected_volume = 0; ///< mm^3
    std::vector<double>         added_volumes;       ///< mm^3, stress-free
    std::vector<double>         volume_changes;      ///< mm^3, of the body
    std::vector<SurfaceMetrics> metrics;
  };


  /// What grows: the fat selected by the region, its growth ratio and the
  /// weights of the growing lobules.
  struct GrowthSelection
  {
    double              selected_volume = 0; ///< mm^3
    double              growth_ratio    = 0; ///< g
    std::vector<double> lobule_weights;
  };


  /**
   * The growth scene's record: after each step the skin elevation on the
   * surface grid, its metrics (SurfaceMetrics), the added and the body's
   * volume, the progress line; from them elevation.csv, growth.csv and the
   * scene's part of summary.json.
   */
  class GrowthRecord
  {
  public:
    GrowthRecord(const Parameters        &parameters,
                 MechanicsModel          &model,
                 const QuasiStaticDriver &driver,
                 ConditionalOStream      &pcout,
                 const GrowthSelection   &selection);

    /// Measures step @p step (the share @p fraction of the growth reached)
    /// and prints its line.
    void
    record(const unsigned int step, const double fraction);

    /// Writes elevation.csv (last step) and growth.csv (every step).
    void
    write_tables(RunOutput &output) const;

    /// Adds the scene's results to @p summary and returns them.
    GrowthResult
    add_to_summary(nlohmann::ordered_json &summary) const;

  private:
    const Parameters          &parameters;
    MechanicsModel            &model;
    const QuasiStaticDriver   &driver;
    ConditionalOStream        &pcout;
    const GrowthSelection      selection;
    const PointLocator         locator;
    GridField                  elevation;
    std::vector<PointLocation> surface;
    GrowthResult               result;
  };
} // namespace ssc

#endif
