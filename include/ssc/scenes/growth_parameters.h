#ifndef ssc_scenes_growth_parameters_h
#define ssc_scenes_growth_parameters_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>

#include <array>
#include <string>
#include <vector>

#include <ssc/base/enum_table.h>

namespace ssc
{
  using namespace dealii;

  /// Where the fat grows: the whole patch, or an ellipsoid around a site.
  enum class GrowthRegionShape
  {
    patch,
    ellipsoid
  };

  constexpr std::array<std::pair<GrowthRegionShape, const char *>, 2>
  enum_table(GrowthRegionShape)
  {
    return {{{GrowthRegionShape::patch, "patch"},
             {GrowthRegionShape::ellipsoid, "ellipsoid"}}};
  }

  /**
   * The growth scene (section "Growth"): fat lobules of the named layers in
   * a region take an isotropic volumetric growth g, the same for all, found
   * so that the stress-free added volume equals Added volume; and how the
   * skin surface that results is measured.
   */
  struct GrowthParameters
  {
    std::vector<std::string> layers    = {"SAT", "DAT"};
    GrowthRegionShape        shape     = GrowthRegionShape::patch;
    Point<3>                 centre    = Point<3>(0, 0, -5);
    Point<3>                 semi_axes = Point<3>(10, 10, 5);
    /// The largest mean growth ratio accepted: fat that grows to eleven
    /// times its volume is beyond adipocyte hypertrophy (cells of obese
    /// people hold a few times the lipid of lean ones) and beyond what a
    /// hyperelastic lobule represents.
    static constexpr double max_growth_ratio = 10;

    double       added_volume       = 1000;
    unsigned int load_steps         = 4;
    double       trend_width        = 4;
    double       grid_spacing       = 0.5;
    double       dimple_depth       = 0.01;
    double       metrics_half_width = 0;
    /// Lognormal spread (standard deviation of ln w) of the lobules' growth
    /// weights w, mean 1: lobules differ (hypertrophy is uneven).
    double lobule_growth_spread = 0;
    /// Probability that a lobule of the region grows at all.
    double growing_lobule_fraction = 1;
    /// Seed of the draws of the lobules' weights.
    unsigned int growth_seed = 1;
    /// How far the septa grow with the fat either side of them (0: not at
    /// all, the hypertrophied lobules stretch them; 1: as a line of the fat
    /// grows, the septa remodel with the lobules).
    double septum_growth = 0;

    /// Whether @p p lies in the region (always, for the whole patch).
    bool
    contains(const Point<3> &p) const;

    /// Declares section "Growth", bound to the members.
    void
    add_parameters(ParameterHandler &prm);

    /// Checks the values (after parsing); throws naming the parameter.
    void
    check() const;
  };
} // namespace ssc

#endif
