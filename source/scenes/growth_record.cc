#include <iomanip>
#include <sstream>

#include <ssc/mechanics/volume_change.h>
#include <ssc/scenes/growth_record.h>

namespace ssc
{
  namespace
  {
    /// The grid of the skin surface (z = 0) on which the elevation is
    /// sampled: the whole patch (the trend needs more than the metrics'
    /// window).
    GridField
    surface_grid(const GrowthParameters &growth, const MeshParameters &mesh)
    {
      GridField          grid;
      const double       hx = mesh.patch_length_x / 2;
      const double       hy = mesh.patch_length_y / 2;
      const unsigned int nx =
        std::max(3., std::round(2 * hx / growth.grid_spacing) + 1);
      const unsigned int ny =
        std::max(3., std::round(2 * hy / growth.grid_spacing) + 1);
      for (unsigned int i = 0; i < nx; ++i)
        grid.x.push_back(-hx + 2 * hx * i / (nx - 1));
      for (unsigned int j = 0; j < ny; ++j)
        grid.y.push_back(-hy + 2 * hy * j / (ny - 1));
      grid.values.assign(nx * ny, 0.);
      return grid;
    }


    /// elevation.csv: x, y, u_z, trend, u_z - trend in the metrics' window.
    std::string
    elevation_csv(const GridField &elevation, const SurfaceMetrics &metrics)
    {
      std::ostringstream csv;
      csv << "x_mm,y_mm,uz_mm,trend_mm,residual_mm\n" << std::setprecision(8);
      for (unsigned int j = metrics.first_y; j <= metrics.last_y; ++j)
        for (unsigned int i = metrics.first_x; i <= metrics.last_x; ++i)
          csv << elevation.x[i] << ',' << elevation.y[j] << ','
              << elevation(i, j) << ',' << metrics.trend(i, j) << ','
              << elevation(i, j) - metrics.trend(i, j) << '\n';
      return csv.str();
    }
  } // namespace


  GrowthRecord::GrowthRecord(const Parameters        &parameters,
                             MechanicsModel          &model,
                             const QuasiStaticDriver &driver,
                             ConditionalOStream      &pcout,
                             const GrowthSelection   &selection)
    : parameters(parameters)
    , model(model)
    , driver(driver)
    , pcout(pcout)
    , selection(selection)
    , locator(model.mesh().triangulation(), model.system().field().mapping())
    , elevation(surface_grid(parameters.growth, parameters.mesh))
  {
    std::vector<Point<3>> surface_points;
    for (const double y : elevation.y)
      for (const double x : elevation.x)
        surface_points.emplace_back(x, y, 0.);
    surface                = locator.locate(surface_points);
    result.selected_volume = selection.selected_volume;
    result.growth_ratio    = selection.growth_ratio;
  }


  void
  GrowthRecord::record(const unsigned int k, const double fraction)
  {
    const GrowthParameters &growth = parameters.growth;
    const ElasticSystem    &system = model.system();
    if (driver.linear() && k == 0)
      {
        if (!parameters.run.test_mode)
          pcout << ", " << driver.statistics()[0].linear_iterations
                << " CG iterations";
        pcout << std::endl;
      }
    std::vector<Tensor<1, 3>> u;
    std::vector<Tensor<2, 3>> gradient;
    system.field().evaluate_at(surface, u, gradient);
    for (unsigned int i = 0; i < u.size(); ++i)
      elevation.values[i] = u[i][2];
    result.metrics.push_back(
      SurfaceMetrics::compute(elevation,
                              growth.trend_width,
                              growth.dimple_depth,
                              growth.metrics_half_width));
    result.added_volumes.push_back(fraction * growth.added_volume);
    result.volume_changes.push_back(
      volume_change(system.field(), system.materials()));
    const SurfaceMetrics &m          = result.metrics.back();
    const StepStatistics &statistics = driver.statistics().back();
    pcout << "Growth step " << k + 1 << " of " << growth.load_steps
          << ": added " << std::setprecision(6) << result.added_volumes.back()
          << " mm^3 (the body's volume " << result.volume_changes.back()
          << " mm^3), elevation max " << m.max_elevation << " mean "
          << m.mean_elevation << " mm, Sa " << m.Sa << " Sq " << m.roughness
          << " Svm " << m.Svm << " mm, dimples " << m.dimples.size();
    if (!driver.linear() && !parameters.run.test_mode)
      pcout << " (" << statistics.newton_iterations << " Newton, "
            << statistics.linear_iterations << " CG iterations, "
            << statistics.cuts << " cuts)";
    pcout << std::endl;
  }


  void
  GrowthRecord::write_tables(RunOutput &output) const
  {
    output.write_text("elevation.csv",
                      elevation_csv(elevation, result.metrics.back()));
    std::ostringstream csv;
    csv << "step,added_volume_mm3,volume_change_mm3,max_elevation_mm,"
           "mean_elevation_mm,"
           "roughness_mm,Sa_mm,Sz_mm,Svm_mm,dimples,max_dimple_depth_mm,"
           "uplift_volume_mm3,"
           "newton_iterations,linear_iterations,load_cuts,wall_time_s\n"
        << std::setprecision(10);
    for (unsigned int k = 0; k < result.metrics.size(); ++k)
      {
        const auto json = result.metrics[k].to_json();
        csv << k + 1 << ',' << result.added_volumes[k] << ','
            << result.volume_changes[k] << ','
            << result.metrics[k].max_elevation << ','
            << result.metrics[k].mean_elevation << ','
            << result.metrics[k].roughness << ',' << result.metrics[k].Sa << ','
            << result.metrics[k].Sz() << ',' << result.metrics[k].Svm << ','
            << result.metrics[k].dimples.size() << ','
            << json["dimples"]["max_depth_mm"].get<double>() << ','
            << result.metrics[k].uplift_volume << ','
            << driver.statistics()[k].newton_iterations << ','
            << driver.statistics()[k].linear_iterations << ','
            << driver.statistics()[k].cuts << ','
            << driver.statistics()[k].wall_time << '\n';
      }
    output.write_text("growth.csv", csv.str());
  }


  GrowthResult
  GrowthRecord::add_to_summary(nlohmann::ordered_json &summary) const
  {
    const GrowthParameters &growth = parameters.growth;
    summary["embedded"]            = model.coupling().embedded_summary();
    summary["solver"]              = driver.summary();
    const SurfaceMetrics &last     = result.metrics.back();
    summary["added_volume_mm3"]    = growth.added_volume;
    summary["max_elevation_mm"]    = last.max_elevation;
    summary["mean_elevation_mm"]   = last.mean_elevation;
    summary["roughness_mm"]        = last.roughness;
    summary["dimples"]             = last.to_json()["dimples"];
    summary["surface"]             = last.surface_json();
    summary["uplift_volume_mm3"]   = last.uplift_volume;
    summary["volume_change_mm3"]   = result.volume_changes.back();
    summary["growth"]              = {
                   {"layers", growth.layers},
                   {"region", to_string(growth.shape)},
                   {"grown_volume_mm3", result.selected_volume},
                   {"growth_ratio", result.growth_ratio},
                   {"growing_lobules", selection.lobule_weights.size()},
                   {"lobule_growth_spread", growth.lobule_growth_spread},
                   {"growing_lobule_fraction", growth.growing_lobule_fraction},
                   {"septum_growth", growth.septum_growth},
                   {"lobule_weights", selection.lobule_weights},
                   {"stress_free_added_volume_mm3",
                    result.growth_ratio * result.selected_volume},
                   {"skin_modulus_factor", parameters.layers.get_skin_modulus_factor()},
                   {"trend_filter_width_mm", growth.trend_width},
                   {"metrics_grid",
                    {{"nx", last.last_x - last.first_x + 1},
                     {"ny", last.last_y - last.first_y + 1},
                     {"spacing_mm", elevation.x[1] - elevation.x[0]},
                     {"half_width_mm", growth.metrics_half_width}}}};
    nlohmann::ordered_json steps = nlohmann::ordered_json::array();
    for (unsigned int k = 0; k < result.metrics.size(); ++k)
      {
        auto entry                 = result.metrics[k].to_json();
        entry["added_volume_mm3"]  = result.added_volumes[k];
        entry["volume_change_mm3"] = result.volume_changes[k];
        entry["surface"]           = result.metrics[k].surface_json();
        steps.push_back(entry);
      }
    summary["steps"] = steps;
    return result;
  }
} // namespace ssc
