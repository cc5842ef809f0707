#include <deal.II/base/exceptions.h>

#include <algorithm>
#include <cmath>

#include <ssc/microstructure/microstructure_parameters.h>

namespace ssc
{
  bool
  MicrostructureRegion::contains(const double x, const double y) const
  {
    switch (shape)
      {
        case RegionShape::everywhere:
          return true;
        case RegionShape::box:
          return std::abs(x - centre[0]) <= half_length_x &&
                 std::abs(y - centre[1]) <= half_length_y;
        case RegionShape::cylinder:
          return std::hypot(x - centre[0], y - centre[1]) <= radius;
      }
    return false;
  }


  BoundingBox<2>
  MicrostructureRegion::bounding_rectangle(const double patch_length_x,
                                           const double patch_length_y) const
  {
    Point<2> lo(-patch_length_x / 2, -patch_length_y / 2);
    Point<2> hi(patch_length_x / 2, patch_length_y / 2);
    if (shape != RegionShape::everywhere)
      {
        const double hx = shape == RegionShape::box ? half_length_x : radius;
        const double hy = shape == RegionShape::box ? half_length_y : radius;
        lo[0]           = std::max(lo[0], centre[0] - hx);
        lo[1]           = std::max(lo[1], centre[1] - hy);
        hi[0]           = std::min(hi[0], centre[0] + hx);
        hi[1]           = std::min(hi[1], centre[1] + hy);
      }
    AssertThrow(hi[0] > lo[0] && hi[1] > lo[1],
                ExcMessage("Microstructure/Region of interest does not "
                           "overlap the patch: move its centre or enlarge "
                           "it."));
    return BoundingBox<2>(std::make_pair(lo, hi));
  }


  BoundingBox<2>
  MicrostructureRegion::realisation_rectangle(const double patch_length_x,
                                              const double patch_length_y) const
  {
    const BoundingBox<2> region =
      bounding_rectangle(patch_length_x, patch_length_y);
    if (realisation_half_width == 0)
      return region;
    const double         w = realisation_half_width;
    const Point<2>       lo(std::max(-patch_length_x / 2, centre[0] - w),
                      std::max(-patch_length_y / 2, centre[1] - w));
    const Point<2>       hi(std::min(patch_length_x / 2, centre[0] + w),
                      std::min(patch_length_y / 2, centre[1] + w));
    const BoundingBox<2> square(std::make_pair(lo, hi));
    for (const Point<2> &corner : {region.get_boundary_points().first,
                                   region.get_boundary_points().second})
      AssertThrow(square.point_inside(corner, 1e-9),
                  ExcMessage("Microstructure/Region of interest/Realisation "
                             "half width = " +
                             std::to_string(w) +
                             " mm does not hold the region of interest: it "
                             "must reach at least as far from the centre as "
                             "the region (or the patch)."));
    return square;
  }


  void
  MicrostructureParameters::add_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Microstructure");
    add_lobule_parameters(prm);
    add_ligament_parameters(prm);
    add_region_parameters(prm);
    add_fasciotomy_parameters(prm);
    prm.leave_subsection();
  }


  void
  MicrostructureParameters::add_lobule_parameters(ParameterHandler &prm)
  {
    prm.add_parameter(
      "Lobules",
      lobules,
      "Build the fat lobules of every SAT and DAT layer as a Lloyd-relaxed "
      "(centroidal) Voronoi tessellation; their walls are the septa (RCS in "
      "SAT, RCP in DAT). The mean lobule size is the layer parameter "
      "'Lobule diameter'.");
    prm.add_parameter("Seed",
                      seed,
                      "Seed of the random number generator (std::mt19937) "
                      "that places lobule seeds and ligaments: the same seed "
                      "gives the same model.",
                      Patterns::Integer(0));
    prm.add_parameter("Lloyd iterations",
                      lloyd_iterations,
                      "Lloyd iterations (seeds moved to the centroids of "
                      "their cells) from uniformly random seeds; 0 keeps the "
                      "Poisson-Voronoi tessellation.",
                      Patterns::Integer(0, 10000));
    prm.add_parameter(
      "Minimum septum area",
      minimum_septum_area,
      "Walls between two lobules whose area is below this fraction of the "
      "squared lobule diameter d^2 are dropped from the septa (they are "
      "slivers from nearly cospherical seeds) and counted in the summary; "
      "the lobule volumes are unaffected.",
      Patterns::Double(0, 1));
    prm.add_parameter("Septum triangle size",
                      septum_triangle_size,
                      "Largest edge (mm) of the triangles of the septa "
                      "surface mesh: every wall is fan-triangulated from its "
                      "centroid and the triangles are subdivided down to "
                      "this size. It only needs to resolve the shape of the "
                      "walls (curved where a layer's thickness varies): the "
                      "mechanics integrates them exactly along the "
                      "background cells.",
                      Patterns::Double(0));
  }


  void
  MicrostructureParameters::add_ligament_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Ligaments");
    prm.add_parameter("Enabled",
                      ligaments,
                      "Build the skin ligaments: straight cables from the "
                      "bottom of the skin to the target layer (Target), "
                      "Density per cm^2, perpendicular to the skin or "
                      "oblique (Inclination).");
    prm.add_parameter(
      "Density",
      ligament_density,
      "Number of skin ligaments per cm^2: a constant or a muParser "
      "expression of x and y (mm), e.g. '1 + 0.1*x' for a linear gradient "
      "or '1 + 2*exp(-(x^2+y^2)/100)' for a radial one. Must be non-negative "
      "on the patch.",
      Patterns::Anything());
    prm.add_parameter("Target",
                      ligament_target,
                      "Where the ligaments end: at the top of the first "
                      "membranous fascia (SM) below the skin, or at the top "
                      "of the deep layer.");
    prm.add_parameter("Segment length",
                      ligament_segment_length,
                      "Length (mm) of the segments of the ligament mesh.",
                      Patterns::Double(0));
    prm.add_parameter(
      "Inclination",
      ligament_inclination,
      "Mean angle (degrees) of the ligaments from the vertical: 0 runs "
      "them perpendicular to the skin; cellulite's fibrous bands are mostly "
      "oblique (84 % of 169 under dimples, Whipple et al., Plast Reconstr "
      "Surg 148:375e, 2021). Each ligament's angle is drawn from a normal "
      "distribution (Inclination spread) cut to [0, 75] degrees, its "
      "azimuth uniformly; it starts where it was placed at the bottom of "
      "the skin and ends where its line meets the target layer.",
      Patterns::Double(0, 75));
    prm.add_parameter("Inclination spread",
                      ligament_inclination_spread,
                      "Standard deviation (degrees) of the ligaments' "
                      "angles from the vertical.",
                      Patterns::Double(0, 90));
    prm.leave_subsection();
  }


  void
  MicrostructureParameters::add_region_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Region of interest");
    prm.add_parameter("Shape",
                      region.shape,
                      "Where the explicit microstructure is built: on the "
                      "whole patch, in a box or in a vertical cylinder "
                      "(through all layers). For a cylinder the lobules are "
                      "tessellated in its bounding box and those whose "
                      "centroid lies outside the cylinder are dropped.");
    prm.add_parameter("Centre x",
                      region.centre[0],
                      "x of the region's centre, mm.",
                      Patterns::Double());
    prm.add_parameter("Centre y",
                      region.centre[1],
                      "y of the region's centre, mm.",
                      Patterns::Double());
    prm.add_parameter("Half length x",
                      region.half_length_x,
                      "Half of the box's extent in x, mm.",
                      Patterns::Double(0));
    prm.add_parameter("Half length y",
                      region.half_length_y,
                      "Half of the box's extent in y, mm.",
                      Patterns::Double(0));
    prm.add_parameter("Radius",
                      region.radius,
                      "Radius of the cylinder, mm.",
                      Patterns::Double(0));
    prm.add_parameter(
      "Realisation half width",
      region.realisation_half_width,
      "0: the lobules and ligaments are drawn at random in the region's "
      "bounding rectangle, so regions of different sizes are different "
      "realisations. > 0: they are drawn in the square of this half width "
      "(mm) about the centre (clipped to the patch) and then cut to the "
      "region, so that growing regions cut one realisation (a "
      "region-of-interest study); it must hold the region.",
      Patterns::Double(0));
    prm.leave_subsection();
  }


  void
  MicrostructureParameters::add_fasciotomy_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Fasciotomy");
    prm.add_parameter("Enabled",
                      fasciotomy.enabled,
                      "Surgical release at a site: the septa whose "
                      "area-weighted centroid and the skin ligaments whose "
                      "axis lie within Radius of the vertical axis through "
                      "the centre are cut (removed). Run a scene with and "
                      "without it to see what the release changes.");
    prm.add_parameter("Centre x",
                      fasciotomy.centre[0],
                      "x of the release site, mm.",
                      Patterns::Double());
    prm.add_parameter("Centre y",
                      fasciotomy.centre[1],
                      "y of the release site, mm.",
                      Patterns::Double());
    prm.add_parameter("Radius",
                      fasciotomy.radius,
                      "Radius of the released cylinder, mm.",
                      Patterns::Double(0));
    prm.leave_subsection();
  }


  void
  MicrostructureParameters::check() const
  {
    AssertThrow(septum_triangle_size > 0,
                ExcMessage("Microstructure/Septum triangle size must be "
                           "positive (mm)."));
    AssertThrow(ligament_segment_length > 0,
                ExcMessage("Microstructure/Ligaments/Segment length must be "
                           "positive (mm)."));
    AssertThrow(region.shape != RegionShape::box ||
                  (region.half_length_x > 0 && region.half_length_y > 0),
                ExcMessage("Microstructure/Region of interest: a box needs "
                           "positive half lengths."));
    AssertThrow(region.shape != RegionShape::cylinder || region.radius > 0,
                ExcMessage("Microstructure/Region of interest: a cylinder "
                           "needs a positive radius."));
    AssertThrow(!fasciotomy.enabled || fasciotomy.radius > 0,
                ExcMessage("Microstructure/Fasciotomy/Radius must be "
                           "positive (mm)."));
    AssertThrow(!fasciotomy.enabled || lobules || ligaments,
                ExcMessage("Microstructure/Fasciotomy is enabled, but there "
                           "is nothing to cut: switch on Microstructure/"
                           "Lobules or Ligaments/Enabled."));
  }
} // namespace ssc
