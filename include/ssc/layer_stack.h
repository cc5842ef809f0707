#ifndef ssc_layer_stack_h
#define ssc_layer_stack_h

#include <deal.II/base/function_parser.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>

#include <memory>
#include <string>
#include <vector>

namespace ssc
{
  using namespace dealii;

  /// Constitutive law of a layer.
  enum class MaterialModel
  {
    linear,
    corotational,
    neo_hookean
  };

  /// Anatomical role of a layer; decides which microstructure it may carry.
  enum class LayerKind
  {
    skin,
    SAT,
    SM,
    DAT,
    deep
  };

  /// Returns the prm spelling of @p kind.
  std::string
  to_string(const LayerKind kind);

  /// Returns the prm spelling of @p model.
  std::string
  to_string(const MaterialModel model);

  /**
   * One layer of the skin/subcutaneous complex: its thickness map
   * t(x, y) in mm (a constant or a muParser expression), its isotropic
   * material and how many background cells resolve it.
   */
  struct Layer
  {
    std::string  name;
    LayerKind    kind;
    std::string  thickness_expression;
    double       youngs_modulus; ///< MPa
    double       poisson_ratio;
    unsigned int n_cells_across;
    /// Ratio of successive cell heights from the top of the layer down.
    double grading;
    /// Mean diameter (mm) of the fat lobules of an SAT or DAT layer (0:
    /// none); the lobule count is the layer volume over the volume of the
    /// sphere of this diameter.
    double lobule_diameter = 0;
    /// Height-to-width ratio of the lobules (> 1: palisade-like SAT).
    double lobule_stretch = 1;
    /// Small-strain linear elasticity or compressible neo-Hookean.
    MaterialModel model = MaterialModel::linear;

    /// Whether this layer can carry lobules (kind SAT or DAT).
    bool
    is_adipose() const
    {
      return kind == LayerKind::SAT || kind == LayerKind::DAT;
    }

    /// Whether the thickness is a plain number (not a function of x, y).
    bool
    has_constant_thickness() const;

    /// Thickness at (x, y), mm.
    double
    thickness(const double x, const double y) const;

    /// Lamé's first parameter, MPa.
    double
    lambda() const;

    /// Shear modulus, MPa.
    double
    mu() const;

    std::shared_ptr<FunctionParser<2>> thickness_function;
  };

  /**
   * The ordered layers, top (skin, z = 0) to bottom. Layer i occupies
   * -depth_{i+1}(x, y) <= z <= -depth_i(x, y) with depth_0 = 0.
   *
   * The set of subsections is decided by the prm file itself (the entry
   * "Layer stack/Layers"), so parsing happens in two passes: first only the
   * list is read (declare_layer_list()), then one subsection per layer is
   * declared (declare_parameters()) and the file is parsed strictly.
   */
  class LayerStack
  {
  public:
    /// Declares "Layer stack/Layers" only (first, tolerant pass).
    static void
    declare_layer_list(ParameterHandler &prm);

    /// Reads the layer names from a handler filled by the first pass.
    static std::vector<std::string>
    parse_layer_list(ParameterHandler &prm);

    /// Declares the list and one subsection per name (second pass).
    static void
    declare_parameters(ParameterHandler               &prm,
                       const std::vector<std::string> &layer_names);

    /// Reads and validates the layers; throws with a clear message.
    void
    parse_parameters(ParameterHandler &prm);

    /**
     * Checks that every thickness is positive over the patch
     * [-Lx/2, Lx/2] x [-Ly/2, Ly/2], sampled on a regular grid.
     */
    void
    check_thickness_positive(const double Lx, const double Ly) const;

    unsigned int
    n_layers() const
    {
      return layers.size();
    }

    const Layer &
    layer(const unsigned int i) const
    {
      return layers[i];
    }

    /// Depth (>= 0, mm) of the top of layer @p i at (x, y); i = n_layers()
    /// gives the bottom of the stack.
    double
    depth_of_interface(const unsigned int i,
                       const double       x,
                       const double       y) const;

    /// Index of the layer containing the point (x, y, z), z <= 0.
    unsigned int
    layer_at(const Point<3> &p) const;

    /// Index of the layer called @p name; throws, naming @p parameter (the
    /// entry that gave the name), if there is none.
    unsigned int
    index_of(const std::string &name, const std::string &parameter) const;

    /// Sets the material model of layer @p i (tests, benchmarks).
    void
    set_model(const unsigned int i, const MaterialModel model)
    {
      layers[i].model = model;
    }

    /// Whether any layer has a nonlinear material model.
    bool
    nonlinear() const;

    /// Adds a layer programmatically (tests, benchmarks).
    void
    add_layer(const std::string &name,
              const LayerKind    kind,
              const std::string &thickness,
              const double       E,
              const double       nu,
              const unsigned int n_cells_across,
              const double       grading         = 1.0,
              const double       lobule_diameter = 0.,
              const double       lobule_stretch  = 1.);

    /// Aging: the factor applied to the moduli of the skin layers.
    double
    get_skin_modulus_factor() const
    {
      return skin_modulus_factor;
    }

  private:
    std::vector<Layer> layers;
    double             skin_modulus_factor = 1.;
  };
} // namespace ssc

#endif
