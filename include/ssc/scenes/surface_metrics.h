#ifndef ssc_scenes_surface_metrics_h
#define ssc_scenes_surface_metrics_h

#include <nlohmann/json.hpp>

#include <vector>

namespace ssc
{
  /// A field sampled on a regular grid: value(i, j) at (x[i], y[j]).
  struct GridField
  {
    std::vector<double> x, y;
    std::vector<double> values; ///< x fastest: values[j * x.size() + i]

    double
    operator()(const unsigned int i, const unsigned int j) const
    {
      return values[j * x.size() + i];
    }
  };

  /// A local minimum of the elevation below its trend.
  struct Dimple
  {
    double x, y;
    double depth; ///< below the trend, mm (positive)
  };

  /**
   * What the skin surface looks like after growth: the elevation u_z(x, y)
   * of the skin (z = 0 at rest), its smooth trend, and what departs from
   * the trend. The trend is the elevation filtered with a Gaussian of
   * standard deviation sigma, normalised by the filtered indicator of the
   * grid so that the edges are not pulled towards zero; the roughness is
   * the root mean square of elevation minus trend; a dimple is a local
   * minimum of elevation minus trend (lower than at the eight neighbouring
   * grid points) at least the dimple depth below the trend.
   */
  struct SurfaceMetrics
  {
    double              max_elevation  = 0; ///< mm
    double              mean_elevation = 0; ///< mm
    double              roughness      = 0; ///< mm
    double              uplift_volume  = 0; ///< integral of u_z, mm^3
    std::vector<Dimple> dimples;
    GridField           trend;

    /// Evaluates @p elevation (spacing uniform in x and in y).
    static SurfaceMetrics
    compute(const GridField &elevation,
            const double     sigma,
            const double     dimple_depth);

    /// The summary.json entries of DESIGN.md §3 (max_elevation_mm,
    /// mean_elevation_mm, roughness_mm, dimples: count, mean and largest
    /// depth) and the uplift volume.
    nlohmann::ordered_json
    to_json() const;
  };
} // namespace ssc

#endif
