#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <ssc/layer_stack.h>

#include <set>
#include <sstream>

namespace ssc
{
  namespace
  {
    constexpr const char *layer_list_entry = "Layers";
    constexpr const char *kinds            = "skin|SAT|SM|DAT|deep";

    LayerKind
    kind_from_string(const std::string &s)
    {
      if (s == "skin")
        return LayerKind::skin;
      if (s == "SAT")
        return LayerKind::SAT;
      if (s == "SM")
        return LayerKind::SM;
      if (s == "DAT")
        return LayerKind::DAT;
      if (s == "deep")
        return LayerKind::deep;
      AssertThrow(false, ExcMessage("Unknown layer kind '" + s + "'."));
      return LayerKind::deep;
    }

    /// Defaults of a layer section, chosen by the layer's name when it names
    /// a kind (Herlin et al. 2014 moduli, typical forearm thicknesses).
    struct LayerDefaults
    {
      const char *kind, *thickness, *modulus, *cells, *lobule_diameter;
    };

    LayerDefaults
    defaults_for(const std::string &name)
    {
      if (name == "skin")
        return {"skin", "1.5", "0.02", "1", "0"};
      if (name == "SM")
        return {"SM", "0.5", "0.06", "1", "0"};
      if (name == "DAT")
        return {"DAT", "3", "0.001", "2", "8"};
      if (name == "deep")
        return {"deep", "10", "0.015", "3", "0"};
      return {"SAT", "3", "0.001", "2", "4"};
    }
  } // namespace


  std::string
  to_string(const LayerKind kind)
  {
    switch (kind)
      {
        case LayerKind::skin:
          return "skin";
        case LayerKind::SAT:
          return "SAT";
        case LayerKind::SM:
          return "SM";
        case LayerKind::DAT:
          return "DAT";
        case LayerKind::deep:
          return "deep";
      }
    return "unknown";
  }


  std::string
  to_string(const MaterialModel model)
  {
    switch (model)
      {
        case MaterialModel::linear:
          return "linear";
        case MaterialModel::corotational:
          return "corotational";
        case MaterialModel::neo_hookean:
          return "neo-Hookean";
      }
    return "unknown";
  }


  double
  Layer::thickness(const double x, const double y) const
  {
    return thickness_function->value(Point<2>(x, y));
  }


  bool
  Layer::has_constant_thickness() const
  {
    try
      {
        Utilities::string_to_double(thickness_expression);
        return true;
      }
    catch (...)
      {
        return false;
      }
  }


  double
  Layer::lambda() const
  {
    return youngs_modulus * poisson_ratio /
           ((1. + poisson_ratio) * (1. - 2. * poisson_ratio));
  }


  double
  Layer::mu() const
  {
    return youngs_modulus / (2. * (1. + poisson_ratio));
  }


  void
  LayerStack::declare_layer_list(ParameterHandler &prm)
  {
    prm.enter_subsection("Layer stack");
    prm.declare_entry(
      layer_list_entry,
      "skin, SAT, SM, DAT, deep",
      Patterns::List(Patterns::Anything()),
      "Names of the layers from the skin surface (z = 0) downwards, comma "
      "separated. Each name gets a subsection of its own below "
      "'Layer stack' with its kind, thickness and material. A kind may repeat "
      "(the abdomen has two membranous fasciae: skin, SAT, SM1, fat, SM2, "
      "DAT, deep).");
    prm.declare_entry(
      "Skin modulus factor",
      "1",
      Patterns::Double(0),
      "Aging: multiplies the Young's modulus of every layer of kind skin "
      "(1: as given; aged skin e.g. 0.5, half as stiff).");
    prm.leave_subsection();
  }


  std::vector<std::string>
  LayerStack::parse_layer_list(ParameterHandler &prm)
  {
    prm.enter_subsection("Layer stack");
    const auto names =
      Utilities::split_string_list(prm.get(layer_list_entry), ',');
    prm.leave_subsection();
    std::vector<std::string> trimmed;
    for (const auto &n : names)
      if (!Utilities::trim(n).empty())
        trimmed.push_back(Utilities::trim(n));
    return trimmed;
  }


  void
  LayerStack::declare_parameters(ParameterHandler               &prm,
                                 const std::vector<std::string> &layer_names)
  {
    declare_layer_list(prm);
    prm.enter_subsection("Layer stack");
    for (const auto &name : layer_names)
      {
        const LayerDefaults d = defaults_for(name);
        prm.enter_subsection(name);
        prm.declare_entry("Kind",
                          d.kind,
                          Patterns::Selection(kinds),
                          "Anatomical kind of this layer: skin (epidermis + "
                          "dermis), SAT (superficial adipose tissue), SM "
                          "(membranous superficial fascia), DAT (deep adipose "
                          "tissue) or deep (muscle, aponeurosis, periosteum).");
        prm.declare_entry(
          "Thickness",
          d.thickness,
          Patterns::Anything(),
          "Thickness of the layer in mm: a constant or a muParser expression "
          "of x and y (mm, patch centred at x = y = 0), e.g. "
          "'3 + 0.05*x'. Must be positive everywhere on the patch.");
        prm.declare_entry("Young's modulus",
                          d.modulus,
                          Patterns::Double(0),
                          "Young's modulus E in MPa (1 kPa = 0.001 MPa). "
                          "Herlin et al. 2014: skin 0.02, fat 0.001, SM 0.06, "
                          "muscle 0.015.");
        prm.declare_entry("Poisson's ratio",
                          "0.49",
                          Patterns::Double(-1, 0.5),
                          "Poisson's ratio nu, -1 < nu < 0.5. Soft tissue is "
                          "nearly incompressible (0.49 and above): use the "
                          "mixed formulation or Q2 elements then.");
        prm.declare_entry("Cells across",
                          d.cells,
                          Patterns::Integer(1),
                          "Number of background cells across the thickness of "
                          "this layer on the coarsest mesh (before global "
                          "refinement).");
        prm.declare_entry(
          "Lobule diameter",
          d.lobule_diameter,
          Patterns::Double(0),
          "Mean diameter (mm) of the fat lobules of an SAT or DAT layer: the "
          "number of lobules is the layer volume over the volume of the "
          "sphere of this diameter. Used when Microstructure/Lobules is on "
          "and the kind is SAT or DAT (ignored otherwise); 0: no lobules in "
          "this layer.");
        prm.declare_entry("Lobule vertical stretch",
                          "1",
                          Patterns::Double(0.1, 10),
                          "Height-to-width ratio of the lobules: > 1 gives "
                          "the vertically elongated, palisade-like lobules of "
                          "the SAT, < 1 the flat lobules of the DAT.");
        prm.declare_entry("Material model",
                          "linear",
                          Patterns::Selection(
                            "linear|corotational|neo-Hookean"),
                          "linear: small-strain isotropic elasticity. "
                          "corotational: the same law on the rotated strain "
                          "U - I of the polar decomposition F = R U (finite "
                          "rotations, small stretches; hyperelastic, so "
                          "Newton's tangent is exact). "
                          "neo-Hookean: compressible neo-Hookean (finite "
                          "strain, isochoric/volumetric split with the same "
                          "small-strain moduli); any nonlinear layer makes the "
                          "scene solve with Newton's method and load steps.");
        prm.declare_entry("Grading",
                          "1",
                          Patterns::Double(0.1, 10),
                          "Ratio of successive cell heights from the top of "
                          "the layer downwards (1 = uniform; > 1 puts small "
                          "cells near the top, as a deep block under a punch "
                          "wants).");
        prm.leave_subsection();
      }
    prm.leave_subsection();
  }


  void
  LayerStack::parse_parameters(ParameterHandler &prm)
  {
    const std::vector<std::string> names = parse_layer_list(prm);
    AssertThrow(!names.empty(),
                ExcMessage("'Layer stack/Layers' is empty: the model needs at "
                           "least one layer (e.g. 'skin, SAT, deep')."));
    std::set<std::string> unique(names.begin(), names.end());
    AssertThrow(unique.size() == names.size(),
                ExcMessage("'Layer stack/Layers' names a layer twice; every "
                           "layer needs a unique name (e.g. SM1, SM2)."));

    layers.clear();
    prm.enter_subsection("Layer stack");
    skin_modulus_factor = prm.get_double("Skin modulus factor");
    AssertThrow(skin_modulus_factor > 0,
                ExcMessage("Layer stack/Skin modulus factor must be "
                           "positive."));
    for (const auto &name : names)
      {
        prm.enter_subsection(name);
        const std::string path = "Layer stack/" + name + "/";
        const double      nu   = prm.get_double("Poisson's ratio");
        AssertThrow(nu > -1. && nu < 0.5,
                    ExcMessage(
                      path + "Poisson's ratio = " + prm.get("Poisson's ratio") +
                      " is outside (-1, 0.5): nu = 0.5 is exactly "
                      "incompressible and not supported; use 0.4999."));
        const double E = prm.get_double("Young's modulus");
        AssertThrow(E > 0.,
                    ExcMessage(path +
                               "Young's modulus must be positive (MPa)."));
        add_layer(name,
                  kind_from_string(prm.get("Kind")),
                  prm.get("Thickness"),
                  E,
                  nu,
                  prm.get_integer("Cells across"),
                  prm.get_double("Grading"),
                  prm.get_double("Lobule diameter"),
                  prm.get_double("Lobule vertical stretch"));
        if (layers.back().kind == LayerKind::skin)
          layers.back().youngs_modulus *= skin_modulus_factor;
        if (prm.get("Material model") == "neo-Hookean")
          layers.back().model = MaterialModel::neo_hookean;
        else if (prm.get("Material model") == "corotational")
          layers.back().model = MaterialModel::corotational;
        prm.leave_subsection();
      }
    prm.leave_subsection();
  }


  unsigned int
  LayerStack::index_of(const std::string &name,
                       const std::string &parameter) const
  {
    for (unsigned int l = 0; l < layers.size(); ++l)
      if (layers[l].name == name)
        return l;
    AssertThrow(false,
                ExcMessage(parameter + " names '" + name +
                           "', which is not a layer of the Layer stack."));
    return numbers::invalid_unsigned_int;
  }


  void
  LayerStack::add_layer(const std::string &name,
                        const LayerKind    kind,
                        const std::string &thickness,
                        const double       E,
                        const double       nu,
                        const unsigned int n_cells_across,
                        const double       grading,
                        const double       lobule_diameter,
                        const double       lobule_stretch)
  {
    Layer layer;
    layer.name                 = name;
    layer.kind                 = kind;
    layer.thickness_expression = thickness;
    layer.youngs_modulus       = E;
    layer.poisson_ratio        = nu;
    layer.n_cells_across       = n_cells_across;
    layer.grading              = grading;
    layer.lobule_diameter      = lobule_diameter;
    layer.lobule_stretch       = lobule_stretch;
    layer.thickness_function   = std::make_shared<FunctionParser<2>>(1);
    try
      {
        layer.thickness_function->initialize("x,y", thickness, {});
        // Evaluate once: muParser reports unknown symbols only on use.
        layer.thickness_function->value(Point<2>());
      }
    catch (...)
      {
        AssertThrow(false,
                    ExcMessage("Layer stack/" + name + "/Thickness = '" +
                               thickness +
                               "' is not a number or a valid muParser "
                               "expression of x and y."));
      }
    layers.push_back(layer);
  }


  void
  LayerStack::check_thickness_positive(const double Lx, const double Ly) const
  {
    const unsigned int n = 40;
    for (const auto &layer : layers)
      for (unsigned int i = 0; i <= n; ++i)
        for (unsigned int j = 0; j <= n; ++j)
          {
            const double x = -Lx / 2 + Lx * i / n;
            const double y = -Ly / 2 + Ly * j / n;
            const double t = layer.thickness(x, y);
            if (!(t > 0.))
              {
                std::ostringstream msg;
                msg << "Layer stack/" << layer.name << "/Thickness = '"
                    << layer.thickness_expression << "' is " << t
                    << " mm at (x, y) = (" << x << ", " << y
                    << "): every layer needs a positive thickness over the "
                       "whole patch.";
                AssertThrow(false, ExcMessage(msg.str()));
              }
          }
  }


  bool
  LayerStack::nonlinear() const
  {
    for (const auto &layer : layers)
      if (layer.model != MaterialModel::linear)
        return true;
    return false;
  }


  double
  LayerStack::depth_of_interface(const unsigned int i,
                                 const double       x,
                                 const double       y) const
  {
    double depth = 0;
    for (unsigned int l = 0; l < i; ++l)
      depth += layers[l].thickness(x, y);
    return depth;
  }


  unsigned int
  LayerStack::layer_at(const Point<3> &p) const
  {
    double depth = 0;
    for (unsigned int l = 0; l < layers.size(); ++l)
      {
        depth += layers[l].thickness(p[0], p[1]);
        if (-p[2] <= depth)
          return l;
      }
    return layers.size() - 1;
  }
} // namespace ssc
