#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <ssc/scenes/growth_parameters.h>

namespace ssc
{
  bool
  GrowthParameters::contains(const Point<3> &p) const
  {
    if (shape == GrowthRegionShape::patch)
      return true;
    double r2 = 0;
    for (unsigned int d = 0; d < 3; ++d)
      r2 += std::pow((p[d] - centre[d]) / semi_axes[d], 2);
    return r2 <= 1.;
  }


  void
  GrowthParameters::add_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Growth");
    prm.add_parameter("Layers",
                      layers,
                      "Names of the layers whose fat grows (layers of the "
                      "Layer stack, usually the adipose ones).",
                      Patterns::List(Patterns::Anything()));
    prm.add_parameter(
      "Region",
      shape,
      "patch: every lobule of those layers grows (fat growth, cellulite); "
      "ellipsoid: the lobules whose centroid lies in the ellipsoid (Centre, "
      "Semi-axes) grow (an injection site). Where a layer carries no "
      "lobules (Microstructure/Lobules off, or outside its region of "
      "interest) the material inside the region grows point by point.");
    prm.add_parameter("Centre",
                      centre,
                      "Centre x, y, z of the ellipsoid, mm (z < 0 below the "
                      "skin surface).",
                      Patterns::List(Patterns::Double(-1e4, 1e4), 3, 3, ","));
    prm.add_parameter("Semi-axes",
                      semi_axes,
                      "Semi-axes of the ellipsoid along x, y, z, mm.",
                      Patterns::List(Patterns::Double(0, 1e4), 3, 3, ","));
    prm.add_parameter("Added volume",
                      added_volume,
                      "Stress-free volume the growth adds, mm^3 (1 cm^3 = "
                      "1000 mm^3): the growth ratio g of the selected "
                      "material is this divided by its volume (each "
                      "lobule's weighted by its Lobule growth spread "
                      "draw), at most 10 (fat eleven times its volume).",
                      Patterns::Double(0));
    prm.add_parameter("Load steps",
                      load_steps,
                      "The added volume is reached in this many equal "
                      "steps, each reported (finite strain: each solved by "
                      "Newton's method with adaptive increments).",
                      Patterns::Integer(1, 1000));
    prm.add_parameter(
      "Trend filter width",
      trend_width,
      "Standard deviation (mm) of the Gaussian filter that gives the smooth "
      "trend of the skin elevation: roughness and dimples are what varies "
      "on shorter scales (the lobules, 2-5 mm), the trend what varies on "
      "longer ones (the swelling as a whole).",
      Patterns::Double(0));
    prm.add_parameter("Grid spacing",
                      grid_spacing,
                      "Spacing (mm) of the grid on which the skin "
                      "elevation is sampled.",
                      Patterns::Double(0));
    prm.add_parameter("Dimple depth",
                      dimple_depth,
                      "A dimple is a local minimum of the elevation at "
                      "least this far (mm) below the trend.",
                      Patterns::Double(0));
    prm.add_parameter("Metrics half width",
                      metrics_half_width,
                      "The surface metrics use the square |x|, |y| <= this "
                      "(mm) around the patch centre, away from the "
                      "supported sides; 0: the whole patch.",
                      Patterns::Double(0));
    prm.add_parameter(
      "Lobule growth spread",
      lobule_growth_spread,
      "Heterogeneous growth: each growing lobule grows by w times the "
      "common growth ratio, w drawn once per lobule from a lognormal "
      "distribution of mean 1 whose ln w has this standard deviation (0: "
      "all lobules alike). The added volume stays the one asked for.",
      Patterns::Double(0, 3));
    prm.add_parameter("Growing lobule fraction",
                      growing_lobule_fraction,
                      "Each lobule of the region grows with this probability "
                      "(1: all of them); the others keep their volume.",
                      Patterns::Double(0, 1));
    prm.add_parameter(
      "Septum growth",
      septum_growth,
      "How far the septa grow with the fat either side of them (finite "
      "and small strain): their stress-free state is stretched in their "
      "plane by (1 + f g)^(1/3), g the mean growth ratio of the two "
      "lobules a septum separates, f this factor. 0: the septa keep their "
      "size and the growing lobules stretch them (hypertrophy inside a "
      "fixed fibrous frame); 1: they grow as a line of the fat does, so "
      "uniform growth of lobules and septa alike is stress-free (the frame "
      "remodels with the fat). How much septa remodel in cellulite is not "
      "measured: a parameter to study, 0 to 1.",
      Patterns::Double(0, 1));
    prm.add_parameter("Random seed",
                      growth_seed,
                      "Seed of the draws of the lobules' growth (the "
                      "lobules' own is Microstructure/Seed).",
                      Patterns::Integer(0));
    prm.leave_subsection();
  }


  void
  GrowthParameters::check() const
  {
    AssertThrow(!layers.empty(), ExcMessage("Growth/Layers names no layer."));
    AssertThrow(shape == GrowthRegionShape::patch ||
                  (semi_axes[0] > 0 && semi_axes[1] > 0 && semi_axes[2] > 0),
                ExcMessage("Growth/Semi-axes must be positive (mm)."));
    AssertThrow(growing_lobule_fraction > 0,
                ExcMessage("Growth/Growing lobule fraction must be above 0 "
                           "(some lobule has to grow)."));
    AssertThrow(trend_width > 0 && grid_spacing > 0,
                ExcMessage("Growth/Trend filter width and Grid spacing must "
                           "be positive (mm)."));
  }
} // namespace ssc
