#ifndef ssc_microstructure_microstructure_parameters_h
#define ssc_microstructure_microstructure_parameters_h

#include <deal.II/base/bounding_box.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>

#include <array>
#include <cmath>
#include <string>

#include <ssc/base/enum_table.h>

namespace ssc
{
  using namespace dealii;

  /// Where the explicit microstructure is built (docs/architecture.md §9: model
  /// only what a scene needs); outside it the layers are homogeneous.
  enum class RegionShape
  {
    everywhere,
    box,
    cylinder
  };

  constexpr std::array<std::pair<RegionShape, const char *>, 3>
  enum_table(RegionShape)
  {
    return {{{RegionShape::everywhere, "everywhere"},
             {RegionShape::box, "box"},
             {RegionShape::cylinder, "cylinder"}}};
  }

  /**
   * The lateral region of interest of the microstructure: the whole patch,
   * an axis-parallel box or a vertical cylinder, through every layer.
   */
  struct MicrostructureRegion
  {
    RegionShape shape = RegionShape::everywhere;
    Point<2>    centre;
    double      half_length_x = 10;
    double      half_length_y = 10;
    double      radius        = 10;
    /// > 0: the random microstructure is drawn in the square of this half
    /// width about the centre and then cut to the region, so that regions
    /// of different sizes cut one realisation; 0: drawn in the region's
    /// bounding rectangle
    double realisation_half_width = 0;

    /// Whether the lateral position (x, y) lies in the region.
    bool
    contains(const double x, const double y) const;

    /// The region's bounding rectangle clipped to the patch
    /// [-Lx/2, Lx/2] x [-Ly/2, Ly/2]; throws if they do not overlap.
    BoundingBox<2>
    bounding_rectangle(const double patch_length_x,
                       const double patch_length_y) const;

    /// Where the random microstructure is drawn: the square of
    /// realisation_half_width clipped to the patch (throws unless it holds
    /// the region's bounding rectangle), or that rectangle.
    BoundingBox<2>
    realisation_rectangle(const double patch_length_x,
                          const double patch_length_y) const;
  };

  /// Where the skin ligaments (retinacula cutis) end.
  enum class LigamentTarget
  {
    SM,
    deep
  };

  constexpr std::array<std::pair<LigamentTarget, const char *>, 2>
  enum_table(LigamentTarget)
  {
    return {{{LigamentTarget::SM, "SM"}, {LigamentTarget::deep, "deep"}}};
  }

  /**
   * A fasciotomy (surgical release, subcision): every septum whose
   * area-weighted centroid and every ligament whose axis lies within
   * @p radius of the vertical axis through @p centre is cut, i.e. removed
   * from the model.
   */
  struct Fasciotomy
  {
    bool     enabled = false;
    Point<2> centre;
    double   radius = 5;

    /// Whether a point at lateral position (x, y) is inside the release.
    bool
    cuts(const double x, const double y) const
    {
      return enabled && std::hypot(x - centre[0], y - centre[1]) <= radius;
    }
  };

  /**
   * Parameters of the procedural microstructure (section "Microstructure"):
   * lobule tessellation of the SAT and DAT layers (their lobule diameters
   * are layer parameters), septa, skin ligaments and the region of interest.
   */
  struct MicrostructureParameters
  {
    bool           lobules                 = false;
    bool           ligaments               = false;
    unsigned int   seed                    = 1;
    unsigned int   lloyd_iterations        = 30;
    double         minimum_septum_area     = 1e-3;
    double         septum_triangle_size    = 2;
    std::string    ligament_density        = "1";
    LigamentTarget ligament_target         = LigamentTarget::SM;
    double         ligament_segment_length = 0.5;
    /// Mean and standard deviation (degrees) of the ligaments' angle from
    /// the vertical; their azimuths are uniform.
    double               ligament_inclination        = 0;
    double               ligament_inclination_spread = 0;
    MicrostructureRegion region;
    Fasciotomy           fasciotomy;

    /// Declares section "Microstructure", bound to the members.
    void
    add_parameters(ParameterHandler &prm);

    /// Checks the values (after parsing); throws naming the parameter.
    void
    check() const;

  private:
    /// Declares the lobule tessellation and its septa.
    void
    add_lobule_parameters(ParameterHandler &prm);

    /// Declares subsection "Ligaments" (the skin ligaments).
    void
    add_ligament_parameters(ParameterHandler &prm);

    /// Declares subsection "Region of interest" (where it is built).
    void
    add_region_parameters(ParameterHandler &prm);

    /// Declares subsection "Fasciotomy" (a surgical release).
    void
    add_fasciotomy_parameters(ParameterHandler &prm);
  };
} // namespace ssc

#endif
