#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <ssc/scenes/growth_parameters.h>

namespace ssc
{
  namespace
  {
    /// Reads "a, b, c" into a point; @p name is for the message.
    Point<3>
    parse_triple(const std::string &text, const std::string &name)
    {
      const auto values =
        Utilities::string_to_double(Utilities::split_string_list(text, ','));
      AssertThrow(values.size() == 3,
                  ExcMessage(name + " = '" + text +
                             "' needs three numbers, e.g. '0, 0, -5'."));
      return Point<3>(values[0], values[1], values[2]);
    }
  } // namespace


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
  GrowthParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Growth");
    prm.declare_entry("Layers",
                      "SAT, DAT",
                      Patterns::List(Patterns::Anything()),
                      "Names of the layers whose fat grows (layers of the "
                      "Layer stack, usually the adipose ones).");
    prm.declare_entry(
      "Region",
      "patch",
      Patterns::Selection("patch|ellipsoid"),
      "patch: every lobule of those layers grows (fat growth, cellulite); "
      "ellipsoid: the lobules whose centroid lies in the ellipsoid (Centre, "
      "Semi-axes) grow (an injection site). Where a layer carries no "
      "lobules (Microstructure/Lobules off, or outside its region of "
      "interest) the material inside the region grows point by point.");
    prm.declare_entry("Centre",
                      "0, 0, -5",
                      Patterns::Anything(),
                      "Centre x, y, z of the ellipsoid, mm (z < 0 below the "
                      "skin surface).");
    prm.declare_entry("Semi-axes",
                      "10, 10, 5",
                      Patterns::Anything(),
                      "Semi-axes of the ellipsoid along x, y, z, mm.");
    prm.declare_entry("Added volume",
                      "1000",
                      Patterns::Double(0),
                      "Stress-free volume the growth adds, mm^3 (1 cm^3 = "
                      "1000 mm^3): the growth ratio g of the selected "
                      "material is this divided by its volume.");
    prm.declare_entry("Load steps",
                      "4",
                      Patterns::Integer(1, 1000),
                      "The added volume is reached in this many equal "
                      "steps, each reported (finite strain: each solved by "
                      "Newton's method with adaptive increments).");
    prm.declare_entry(
      "Trend filter width",
      "4",
      Patterns::Double(0),
      "Standard deviation (mm) of the Gaussian filter that gives the smooth "
      "trend of the skin elevation: roughness and dimples are what varies "
      "on shorter scales (the lobules, 2-5 mm), the trend what varies on "
      "longer ones (the swelling as a whole).");
    prm.declare_entry("Grid spacing",
                      "0.5",
                      Patterns::Double(0),
                      "Spacing (mm) of the grid on which the skin "
                      "elevation is sampled.");
    prm.declare_entry("Dimple depth",
                      "0.01",
                      Patterns::Double(0),
                      "A dimple is a local minimum of the elevation at "
                      "least this far (mm) below the trend.");
    prm.declare_entry("Metrics half width",
                      "0",
                      Patterns::Double(0),
                      "The surface metrics use the square |x|, |y| <= this "
                      "(mm) around the patch centre, away from the "
                      "supported sides; 0: the whole patch.");
    prm.leave_subsection();
  }


  void
  GrowthParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Growth");
    layers.clear();
    for (const auto &name : Utilities::split_string_list(prm.get("Layers")))
      if (!Utilities::trim(name).empty())
        layers.push_back(Utilities::trim(name));
    shape  = prm.get("Region") == "ellipsoid" ? GrowthRegionShape::ellipsoid :
                                                GrowthRegionShape::patch;
    centre = parse_triple(prm.get("Centre"), "Growth/Centre");
    semi_axes          = parse_triple(prm.get("Semi-axes"), "Growth/Semi-axes");
    added_volume       = prm.get_double("Added volume");
    load_steps         = prm.get_integer("Load steps");
    trend_width        = prm.get_double("Trend filter width");
    grid_spacing       = prm.get_double("Grid spacing");
    dimple_depth       = prm.get_double("Dimple depth");
    metrics_half_width = prm.get_double("Metrics half width");
    prm.leave_subsection();
    AssertThrow(!layers.empty(), ExcMessage("Growth/Layers names no layer."));
    AssertThrow(shape == GrowthRegionShape::patch ||
                  (semi_axes[0] > 0 && semi_axes[1] > 0 && semi_axes[2] > 0),
                ExcMessage("Growth/Semi-axes must be positive (mm)."));
    AssertThrow(trend_width > 0 && grid_spacing > 0,
                ExcMessage("Growth/Trend filter width and Grid spacing must "
                           "be positive (mm)."));
  }
} // namespace ssc
