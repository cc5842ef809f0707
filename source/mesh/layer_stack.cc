#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>

#include <ssc/base/surface_expression.h>
#include <ssc/mesh/layer_stack.h>

namespace ssc
{
  namespace
  {
    constexpr const char *layer_list_entry = "Layers";

    /// Defaults of a layer section, chosen by the layer's name when it names
    /// a kind (Herlin et al. 2014 moduli, typical forearm thicknesses); a
    /// layer with another name has no default kind.
    struct LayerDefaults
    {
      const char  *kind, *thickness;
      double       modulus;
      unsigned int cells;
      double       lobule_diameter;
    };

    LayerDefaults
    defaults_for(const std::string &name)
    {
      if (name == "skin")
        return {"skin", "1.5", 0.02, 1, 0};
      if (name == "SAT")
        return {"SAT", "3", 0.001, 2, 4};
      if (name == "SM")
        return {"SM", "0.5", 0.06, 1, 0};
      if (name == "DAT")
        return {"DAT", "3", 0.001, 2, 8};
      if (name == "deep")
        return {"deep", "10", 0.015, 3, 0};
      return {"", "3", 0.001, 2, 4};
    }
  } // namespace


  double
  Layer::thickness(const double x, const double y) const
  {
    if (!std::isnan(constant_thickness))
      return constant_thickness;
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


  void
  LayerStack::add_layer_list(ParameterHandler &prm)
  {
    prm.enter_subsection("Layer stack");
    prm.add_parameter(
      layer_list_entry,
      layer_list,
      "Names of the layers from the skin surface (z = 0) downwards, comma "
      "separated. Each name gets a subsection of its own below "
      "'Layer stack' with its kind, thickness and material. A kind may repeat "
      "(the abdomen has two membranous fasciae: skin, SAT, SM1, fat, SM2, "
      "DAT, deep); a name that is not a kind must set its Kind.",
      Patterns::List(Patterns::Anything()));
    prm.add_parameter(
      "Skin modulus factor",
      skin_modulus_factor,
      "Aging: multiplies the Young's modulus of every layer of kind skin "
      "(1: as given; aged skin e.g. 0.5, half as stiff).",
      Patterns::Double(0, 1e3));
    prm.leave_subsection();
  }


  std::vector<std::string>
  LayerStack::layer_names() const
  {
    std::vector<std::string> trimmed;
    for (const auto &n : Utilities::split_string_list(layer_list, ','))
      if (!Utilities::trim(n).empty())
        trimmed.push_back(Utilities::trim(n));
    return trimmed;
  }


  void
  LayerStack::add_parameters(ParameterHandler               &prm,
                             const std::vector<std::string> &layer_names)
  {
    add_layer_list(prm);
    layers.assign(layer_names.size(), Layer());
    prm.enter_subsection("Layer stack");
    for (unsigned int l = 0; l < layer_names.size(); ++l)
      {
        Layer              &layer  = layers[l];
        const LayerDefaults d      = defaults_for(layer_names[l]);
        layer.name                 = layer_names[l];
        layer.kind_name            = d.kind;
        layer.thickness_expression = d.thickness;
        layer.given_youngs_modulus = d.modulus;
        layer.n_cells_across       = d.cells;
        layer.lobule_diameter      = d.lobule_diameter;
        prm.enter_subsection(layer.name);
        prm.add_parameter("Kind",
                          layer.kind_name,
                          "Anatomical kind of this layer: skin (epidermis + "
                          "dermis), SAT (superficial adipose tissue), SM "
                          "(membranous superficial fascia), DAT (deep adipose "
                          "tissue) or deep (muscle, aponeurosis, periosteum). "
                          "Required for a layer whose name is not a kind.",
                          Patterns::Anything());
        prm.add_parameter(
          "Thickness",
          layer.thickness_expression,
          "Thickness of the layer in mm: a constant or a muParser expression "
          "of x and y (mm, patch centred at x = y = 0), e.g. "
          "'3 + 0.05*x'. Must be positive everywhere on the patch.",
          Patterns::Anything());
        prm.add_parameter("Young's modulus",
                          layer.given_youngs_modulus,
                          "Young's modulus E in MPa (1 kPa = 0.001 MPa). "
                          "Herlin et al. 2014: skin 0.02, fat 0.001, SM 0.06, "
                          "muscle 0.015.",
                          Patterns::Double(0, 1e5));
        prm.add_parameter("Poisson's ratio",
                          layer.poisson_ratio,
                          "Poisson's ratio nu, -1 < nu < 0.5. Soft tissue is "
                          "nearly incompressible (0.49 and above): use the "
                          "mixed formulation or Q2 elements then.",
                          Patterns::Double(-1, 0.5));
        prm.add_parameter("Cells across",
                          layer.n_cells_across,
                          "Number of background cells across the thickness of "
                          "this layer on the coarsest mesh (before global "
                          "refinement).",
                          Patterns::Integer(1, 1000));
        prm.add_parameter(
          "Lobule diameter",
          layer.lobule_diameter,
          "Mean diameter (mm) of the fat lobules of an SAT or DAT layer: the "
          "number of lobules is the layer volume over the volume of the "
          "sphere of this diameter. Used when Microstructure/Lobules is on "
          "and the kind is SAT or DAT (ignored otherwise); 0: no lobules in "
          "this layer.",
          Patterns::Double(0, 1e4));
        prm.add_parameter("Lobule vertical stretch",
                          layer.lobule_stretch,
                          "Height-to-width ratio of the lobules: > 1 gives "
                          "the vertically elongated, palisade-like lobules of "
                          "the SAT, < 1 the flat lobules of the DAT.",
                          Patterns::Double(0.1, 10));
        prm.add_parameter(
          "Prestretch",
          layer.prestretch,
          "The in-plane stretch of the layer as imaged over its stress-free "
          "state (1: none): the layer carries the in vivo pre-tension of "
          "the deformation diag(s, s, 1/s^2) before any load, held by the "
          "patch's sides (with free sides it contracts there). Skin: about "
          "6 N/m on the lower anterior forearm "
          "and 11 N/m on the upper (Flynn et al. 2011, Ann Biomed Eng "
          "39:1935), a prestretch of about 1.2 in porcine skin (Buganza "
          "Tepole et al. 2015). Finite-strain laws only.",
          Patterns::Double(0.5, 2.));
        prm.enter_subsection("Viscoelasticity");
        prm.add_parameter(
          "Relative moduli",
          layer.relative_moduli,
          "The deviatoric Prony series of a visco-elastic layer: the "
          "fractions g_i of the instantaneous shear modulus (E and nu above) "
          "that relax with the times below, g(t) = 1 - sum g_i (1 - "
          "exp(-t/tau_i)); each in (0, 1), their sum below 1. Empty: "
          "elastic. Porcine subdermal fat: one term, 0.39 +- 0.03 (Sims et "
          "al. 2010, Biomech Model Mechanobiol 9:703); in vivo lower-limb "
          "soft tissue (quasi-linear): 0.03-0.28 (Zheng & Mak 1999, J "
          "Biomech Eng 121:330). Finite-strain laws only; the volumetric "
          "energy stays elastic.",
          Patterns::List(Patterns::Double(), 0, 100, ","));
        prm.add_parameter(
          "Relaxation times",
          layer.relaxation_times,
          "The relaxation times tau_i (s) of the Prony terms, one per "
          "relative modulus, each positive. Porcine subdermal fat: 700 +- "
          "255 s (Sims et al. 2010); in vivo lower limb: 0.05-8.9 s (Zheng & "
          "Mak 1999). A load step without time (every scene but a "
          "time-dependent one) sees the instantaneous response.",
          Patterns::List(Patterns::Double(), 0, 100, ","));
        prm.leave_subsection();
        prm.add_parameter(
          "Material model",
          layer.material_model,
          "The constitutive law of this layer, by name: linear (small strain), "
          "or a finite-strain law (corotational, neo-Hookean, Saint "
          "Venant-Kirchhoff, ...), each with the small-strain moduli above; "
          "the laws and the parameters each owns are the subsections of this "
          "section. Any finite-strain layer makes the scene solve with "
          "Newton's method and load steps.",
          Patterns::Anything());
        prm.add_parameter("Grading",
                          layer.grading,
                          "Ratio of successive cell heights from the top of "
                          "the layer downwards (1 = uniform; > 1 puts small "
                          "cells near the top, as a deep block under a punch "
                          "wants).",
                          Patterns::Double(0.1, 10));
        prm.leave_subsection();
      }
    prm.leave_subsection();
  }


  void
  LayerStack::finalise()
  {
    const std::vector<std::string> names = layer_names();
    AssertThrow(!names.empty(),
                ExcMessage("'Layer stack/Layers' is empty: the model needs at "
                           "least one layer (e.g. 'skin, SAT, deep')."));
    std::set<std::string> unique(names.begin(), names.end());
    AssertThrow(unique.size() == names.size(),
                ExcMessage("'Layer stack/Layers' names a layer twice; every "
                           "layer needs a unique name (e.g. SM1, SM2)."));
    AssertThrow(names.size() == layers.size(),
                ExcMessage("The layer sections do not match 'Layer "
                           "stack/Layers'."));
    AssertThrow(skin_modulus_factor > 0,
                ExcMessage("Layer stack/Skin modulus factor must be "
                           "positive."));
    for (Layer &layer : layers)
      {
        const std::string path = "Layer stack/" + layer.name + "/";
        AssertThrow(!layer.kind_name.empty(),
                    ExcMessage(path + "Kind must be set: '" + layer.name +
                               "' is not one of the kinds " +
                               enum_names<LayerKind>() +
                               ", so it has no default kind."));
        try
          {
            layer.kind = enum_from_string<LayerKind>(layer.kind_name);
          }
        catch (const ExceptionBase &)
          {
            AssertThrow(false,
                        ExcMessage(path + "Kind = '" + layer.kind_name +
                                   "' is not one of " +
                                   enum_names<LayerKind>() + "."));
          }
        std::ostringstream nu;
        nu << layer.poisson_ratio;
        AssertThrow(layer.poisson_ratio >= min_poisson_ratio &&
                      layer.poisson_ratio < 0.5,
                    ExcMessage(path + "Poisson's ratio = " + nu.str() +
                               " is outside [-0.9, 0.5): nu = 0.5 is exactly "
                               "incompressible and not supported (use "
                               "0.4999); below -0.9 the bulk modulus "
                               "vanishes against the shear modulus."));
        AssertThrow(layer.given_youngs_modulus > 0.,
                    ExcMessage(path +
                               "Young's modulus must be positive (MPa)."));
        layer.youngs_modulus =
          layer.given_youngs_modulus *
          (layer.kind == LayerKind::skin ? skin_modulus_factor : 1.);
        initialise_thickness(layer);
      }
    // a contrast beyond this leaves the stiff layers rigid to round-off
    // and the linear solver without a usable residual
    const auto [softest, stiffest] =
      std::minmax_element(layers.begin(),
                          layers.end(),
                          [](const Layer &a, const Layer &b) {
                            return a.youngs_modulus < b.youngs_modulus;
                          });
    std::ostringstream contrast;
    contrast << "Layer stack: Young's modulus of '" << stiffest->name << "' ("
             << stiffest->youngs_modulus << " MPa) is more than "
             << max_modulus_contrast << " times that of '" << softest->name
             << "' (" << softest->youngs_modulus
             << " MPa): the stiffer layer would be rigid to round-off; "
                "model it as a support or bring the moduli closer.";
    AssertThrow(stiffest->youngs_modulus <=
                  max_modulus_contrast * softest->youngs_modulus,
                ExcMessage(contrast.str()));
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
    layer.kind_name            = to_string(kind);
    layer.kind                 = kind;
    layer.thickness_expression = thickness;
    layer.given_youngs_modulus = E;
    layer.youngs_modulus       = E;
    layer.poisson_ratio        = nu;
    layer.n_cells_across       = n_cells_across;
    layer.grading              = grading;
    layer.lobule_diameter      = lobule_diameter;
    layer.lobule_stretch       = lobule_stretch;
    initialise_thickness(layer);
    layer_list = (layers.empty() ? "" : layer_list + ", ") + name;
    layers.push_back(layer);
  }


  void
  LayerStack::initialise_thickness(Layer &layer)
  {
    layer.thickness_function =
      parse_surface_expression(layer.thickness_expression,
                               "Layer stack/" + layer.name + "/Thickness");
    layer.constant_thickness = layer.has_constant_thickness() ?
                                 layer.thickness_function->value(Point<2>()) :
                                 std::numeric_limits<double>::quiet_NaN();
  }


  void
  LayerStack::check_thickness(const Layer &layer,
                              const double x,
                              const double y)
  {
    const double t = layer.thickness(x, y);
    if (t >= min_thickness && t <= max_thickness)
      return;
    std::ostringstream msg;
    msg << "Layer stack/" << layer.name << "/Thickness = '"
        << layer.thickness_expression << "' is " << t << " mm at (x, y) = ("
        << x << ", " << y << "): every layer needs a finite thickness between "
        << min_thickness << " and " << max_thickness
        << " mm over the whole patch.";
    AssertThrow(false, ExcMessage(msg.str()));
  }


  void
  LayerStack::check_thickness_positive(const double Lx, const double Ly) const
  {
    const unsigned int n = 40;
    for (const auto &layer : layers)
      for (unsigned int i = 0; i <= n; ++i)
        for (unsigned int j = 0; j <= n; ++j)
          check_thickness(layer, -Lx / 2 + Lx * i / n, -Ly / 2 + Ly * j / n);
  }


  void
  LayerStack::check_thickness_at(const double x, const double y) const
  {
    for (const auto &layer : layers)
      check_thickness(layer, x, y);
  }


  void
  LayerStack::check_mirror_symmetric(const double Lx, const double Ly) const
  {
    const unsigned int n = 20;
    for (const auto &layer : layers)
      if (!layer.has_constant_thickness())
        for (unsigned int i = 0; i <= n; ++i)
          for (unsigned int j = 0; j <= n; ++j)
            {
              const double x = Lx / 2 * i / n, y = Ly / 2 * j / n;
              const double t = layer.thickness(x, y);
              for (const auto &[xm, ym] : {std::pair(-x, y), std::pair(x, -y)})
                {
                  const double tm = layer.thickness(xm, ym);
                  if (std::abs(tm - t) <= 1e-9 * std::max(1., std::abs(t)))
                    continue;
                  std::ostringstream msg;
                  msg << "Layer stack/" << layer.name << "/Thickness = '"
                      << layer.thickness_expression << "' is " << t
                      << " mm at (x, y) = (" << x << ", " << y << ") but " << tm
                      << " mm at the mirrored point (" << xm << ", " << ym
                      << "): Mesh/Symmetry = quarter models a problem "
                         "symmetric about x = 0 and y = 0; set Symmetry = "
                         "none for this layer stack.";
                  AssertThrow(false, ExcMessage(msg.str()));
                }
            }
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
