#ifndef ssc_scenes_growth_parameters_h
#define ssc_scenes_growth_parameters_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>

#include <string>
#include <vector>

namespace ssc
{
  using namespace dealii;

  /// Where the fat grows: the whole patch, or an ellipsoid around a site.
  enum class GrowthRegionShape
  {
    patch,
    ellipsoid
  };

  /**
   * The growth scene (section "Growth"): fat lobules of the named layers in
   * a region take an isotropic volumetric growth g, the same for all, found
   * so that the stress-free added volume equals Added volume; and how the
   * skin surface that results is measured.
   */
  struct GrowthParameters
  {
    std::vector<std::string> layers             = {"SAT", "DAT"};
    GrowthRegionShape        shape              = GrowthRegionShape::patch;
    Point<3>                 centre             = Point<3>(0, 0, -5);
    Point<3>                 semi_axes          = Point<3>(10, 10, 5);
    double                   added_volume       = 1000;
    unsigned int             load_steps         = 4;
    double                   trend_width        = 4;
    double                   grid_spacing       = 0.5;
    double                   dimple_depth       = 0.01;
    double                   metrics_half_width = 0;

    /// Whether @p p lies in the region (always, for the whole patch).
    bool
    contains(const Point<3> &p) const;

    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm);
  };
} // namespace ssc

#endif
