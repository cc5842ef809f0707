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
   * the trend. The trend is the least-squares plane of the elevation plus
   * the Gaussian filter (standard deviation sigma) of what departs from the
   * plane, normalised by the filtered indicator of the grid so that the
   * edges are not pulled towards zero: a tilted plane is its own trend. The
   * trend uses the whole grid, the metrics only the central window
   * |x|, |y| <= half width (away from the grid's edges); the roughness is
   * the root mean square of elevation minus trend; a dimple is a local
   * minimum of the elevation less the plane (lower than at the eight
   * neighbouring grid points) at least the dimple depth below the trend.
   *
   * The areal parameters of ISO 25178-2 are those of the residual r =
   * elevation - trend over the window (the scale-limited surface; the
   * trend is the L-filter, a Gaussian of cut-off wavelength about
   * sigma / 0.187): Sa the mean of |r|, Sq its root mean square, Sp the
   * highest peak, Sv the deepest valley, Sz = Sp + Sv. Clinical scans of
   * cellulite (Smalls et al., J Cosmet Sci 56:105, 2005, TrueMap) also
   * report the profile means Spm and Svm: the highest peak and the deepest
   * valley of each profile (grid line along x), averaged over the profiles;
   * their Sz is Spm + Svm and their St is ISO's Sz.
   */
  struct SurfaceMetrics
  {
    double              max_elevation  = 0; ///< mm
    double              mean_elevation = 0; ///< mm
    double              roughness      = 0; ///< mm, Sq
    double              Sa             = 0; ///< mean |r|, mm
    double              Sp             = 0; ///< highest peak of r, mm
    double              Sv             = 0; ///< deepest valley of r, mm
    double              Spm = 0; ///< mean of the profiles' highest peaks, mm
    double              Svm = 0; ///< mean of the profiles' deepest valleys, mm
    double              uplift_volume = 0; ///< integral of u_z, mm^3
    std::vector<Dimple> dimples;
    GridField           trend;
    /// The grid indices of the window, both ends included.
    unsigned int first_x = 0, last_x = 0, first_y = 0, last_y = 0;

    /// ISO 25178's maximum height Sz = Sp + Sv, mm.
    double
    Sz() const
    {
      return Sp + Sv;
    }

    /// Evaluates @p elevation (spacing uniform in x and in y) in the window
    /// of @p half_width (0: the whole grid).
    static SurfaceMetrics
    compute(const GridField &elevation,
            const double     sigma,
            const double     dimple_depth,
            const double     half_width = 0);

    /// The summary.json entries of docs/architecture.md §7 (max_elevation_mm,
    /// mean_elevation_mm, roughness_mm, dimples: count, mean and largest
    /// depth) and the uplift volume.
    nlohmann::ordered_json
    to_json() const;

    /// The summary.json entry `surface` of docs/architecture.md §7: Sa_mm,
    /// Sq_mm, Sp_mm, Sv_mm, Sz_mm (ISO 25178, Sp + Sv), Spm_mm, Svm_mm and the
    /// dimples.
    nlohmann::ordered_json
    surface_json() const;
  };
} // namespace ssc

#endif
