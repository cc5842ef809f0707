#include <deal.II/base/exceptions.h>

#include <ssc/microstructure/microstructure_parameters.h>

#include <algorithm>
#include <cmath>

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


  void
  MicrostructureParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Microstructure");
    prm.declare_entry(
      "Lobules",
      "false",
      Patterns::Bool(),
      "Build the fat lobules of every SAT and DAT layer as a Lloyd-relaxed "
      "(centroidal) Voronoi tessellation; their walls are the septa (RCS in "
      "SAT, RCP in DAT). The mean lobule size is the layer parameter "
      "'Lobule diameter'.");
    prm.declare_entry("Ligaments",
                      "false",
                      Patterns::Bool(),
                      "Build the skin ligaments: straight cables "
                      "perpendicular to the skin, from the bottom of the "
                      "skin to the target layer.");
    prm.declare_entry("Seed",
                      "1",
                      Patterns::Integer(0),
                      "Seed of the random number generator (std::mt19937) "
                      "that places lobule seeds and ligaments: the same seed "
                      "gives the same model.");
    prm.declare_entry("Lloyd iterations",
                      "30",
                      Patterns::Integer(0, 10000),
                      "Lloyd iterations (seeds moved to the centroids of "
                      "their cells) from uniformly random seeds; 0 keeps the "
                      "Poisson-Voronoi tessellation.");
    prm.declare_entry(
      "Minimum septum area",
      "1e-3",
      Patterns::Double(0, 1),
      "Walls between two lobules whose area is below this fraction of the "
      "squared lobule diameter d^2 are dropped from the septa (they are "
      "slivers from nearly cospherical seeds) and counted in the summary; "
      "the lobule volumes are unaffected.");
    prm.declare_entry("Septum triangle size",
                      "2",
                      Patterns::Double(0),
                      "Largest edge (mm) of the triangles of the septa "
                      "surface mesh: every wall is fan-triangulated from its "
                      "centroid and the triangles are subdivided down to "
                      "this size. It only needs to resolve the shape of the "
                      "walls (curved where a layer's thickness varies): the "
                      "mechanics integrates them exactly along the "
                      "background cells.");
    prm.enter_subsection("Ligaments");
    prm.declare_entry(
      "Density",
      "1",
      Patterns::Anything(),
      "Number of skin ligaments per cm^2: a constant or a muParser "
      "expression of x and y (mm), e.g. '1 + 0.1*x' for a linear gradient "
      "or '1 + 2*exp(-(x^2+y^2)/100)' for a radial one. Must be non-negative "
      "on the patch.");
    prm.declare_entry("Target",
                      "SM",
                      Patterns::Selection("SM|deep"),
                      "Where the ligaments end: at the top of the first "
                      "membranous fascia (SM) below the skin, or at the top "
                      "of the deep layer.");
    prm.declare_entry("Segment length",
                      "0.5",
                      Patterns::Double(0),
                      "Length (mm) of the segments of the ligament mesh.");
    prm.leave_subsection();
    prm.enter_subsection("Region of interest");
    prm.declare_entry("Shape",
                      "everywhere",
                      Patterns::Selection("everywhere|box|cylinder"),
                      "Where the explicit microstructure is built: on the "
                      "whole patch, in a box or in a vertical cylinder "
                      "(through all layers). For a cylinder the lobules are "
                      "tessellated in its bounding box and those whose "
                      "centroid lies outside the cylinder are dropped.");
    prm.declare_entry("Centre x",
                      "0",
                      Patterns::Double(),
                      "x of the region's centre, mm.");
    prm.declare_entry("Centre y",
                      "0",
                      Patterns::Double(),
                      "y of the region's centre, mm.");
    prm.declare_entry("Half length x",
                      "10",
                      Patterns::Double(0),
                      "Half of the box's extent in x, mm.");
    prm.declare_entry("Half length y",
                      "10",
                      Patterns::Double(0),
                      "Half of the box's extent in y, mm.");
    prm.declare_entry("Radius",
                      "10",
                      Patterns::Double(0),
                      "Radius of the cylinder, mm.");
    prm.leave_subsection();
    prm.enter_subsection("Fasciotomy");
    prm.declare_entry("Enabled",
                      "false",
                      Patterns::Bool(),
                      "Surgical release at a site: the septa whose "
                      "area-weighted centroid and the skin ligaments whose "
                      "axis lie within Radius of the vertical axis through "
                      "the centre are cut (removed). Run a scene with and "
                      "without it to see what the release changes.");
    prm.declare_entry("Centre x",
                      "0",
                      Patterns::Double(),
                      "x of the release site, mm.");
    prm.declare_entry("Centre y",
                      "0",
                      Patterns::Double(),
                      "y of the release site, mm.");
    prm.declare_entry("Radius",
                      "5",
                      Patterns::Double(0),
                      "Radius of the released cylinder, mm.");
    prm.leave_subsection();
    prm.leave_subsection();
  }


  void
  MicrostructureParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Microstructure");
    lobules              = prm.get_bool("Lobules");
    ligaments            = prm.get_bool("Ligaments");
    seed                 = prm.get_integer("Seed");
    lloyd_iterations     = prm.get_integer("Lloyd iterations");
    minimum_septum_area  = prm.get_double("Minimum septum area");
    septum_triangle_size = prm.get_double("Septum triangle size");
    AssertThrow(septum_triangle_size > 0,
                ExcMessage("Microstructure/Septum triangle size must be "
                           "positive (mm)."));
    prm.enter_subsection("Ligaments");
    ligament_density = prm.get("Density");
    ligament_target =
      prm.get("Target") == "deep" ? LigamentTarget::deep : LigamentTarget::SM;
    ligament_segment_length = prm.get_double("Segment length");
    AssertThrow(ligament_segment_length > 0,
                ExcMessage("Microstructure/Ligaments/Segment length must be "
                           "positive (mm)."));
    prm.leave_subsection();
    prm.enter_subsection("Region of interest");
    const std::string shape_name = prm.get("Shape");
    region.shape                 = shape_name == "box"      ? RegionShape::box :
                                   shape_name == "cylinder" ? RegionShape::cylinder :
                                                              RegionShape::everywhere;
    region.centre =
      Point<2>(prm.get_double("Centre x"), prm.get_double("Centre y"));
    region.half_length_x = prm.get_double("Half length x");
    region.half_length_y = prm.get_double("Half length y");
    region.radius        = prm.get_double("Radius");
    AssertThrow(region.shape != RegionShape::box ||
                  (region.half_length_x > 0 && region.half_length_y > 0),
                ExcMessage("Microstructure/Region of interest: a box needs "
                           "positive half lengths."));
    AssertThrow(region.shape != RegionShape::cylinder || region.radius > 0,
                ExcMessage("Microstructure/Region of interest: a cylinder "
                           "needs a positive radius."));
    prm.leave_subsection();
    prm.enter_subsection("Fasciotomy");
    fasciotomy.enabled = prm.get_bool("Enabled");
    fasciotomy.centre =
      Point<2>(prm.get_double("Centre x"), prm.get_double("Centre y"));
    fasciotomy.radius = prm.get_double("Radius");
    AssertThrow(!fasciotomy.enabled || fasciotomy.radius > 0,
                ExcMessage("Microstructure/Fasciotomy/Radius must be "
                           "positive (mm)."));
    AssertThrow(!fasciotomy.enabled || lobules || ligaments,
                ExcMessage("Microstructure/Fasciotomy is enabled, but there "
                           "is nothing to cut: switch on Microstructure/"
                           "Lobules or Ligaments."));
    prm.leave_subsection();
    prm.leave_subsection();
  }
} // namespace ssc
