#ifndef ssc_mesh_layer_stack_h
#define ssc_mesh_layer_stack_h

#include <deal.II/base/function_parser.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>

#include <array>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include <ssc/base/enum_table.h>

namespace ssc
{
  using namespace dealii;

  /// Anatomical role of a layer; decides which microstructure it may carry.
  enum class LayerKind
  {
    skin,
    SAT,
    SM,
    DAT,
    deep
  };

  constexpr std::array<std::pair<LayerKind, const char *>, 5>
  enum_table(LayerKind)
  {
    return {{{LayerKind::skin, "skin"},
             {LayerKind::SAT, "SAT"},
             {LayerKind::SM, "SM"},
             {LayerKind::DAT, "DAT"},
             {LayerKind::deep, "deep"}}};
  }

  /**
   * One layer of the skin/subcutaneous complex: its thickness map
   * t(x, y) in mm (a constant or a muParser expression), how many
   * background cells resolve it, its small-strain moduli and the name of
   * its constitutive law (materials/ makes the law, with the parameters the
   * law owns).
   */
  struct Layer
  {
    std::string name;
    /// The prm entry Kind ("" until given: a layer whose name is not a
    /// kind must say which kind it is).
    std::string kind_name;
    LayerKind   kind = LayerKind::SAT;
    std::string thickness_expression;
    /// Young's modulus as given (MPa), and as used: times Layer stack/Skin
    /// modulus factor for layers of kind skin.
    double       given_youngs_modulus = 0;
    double       youngs_modulus       = 0;
    double       poisson_ratio        = 0.49;
    unsigned int n_cells_across       = 1;
    /// Ratio of successive cell heights from the top of the layer down.
    double grading = 1;
    /// Mean diameter (mm) of the fat lobules of an SAT or DAT layer (0:
    /// none); the lobule count is the layer volume over the volume of the
    /// sphere of this diameter.
    double lobule_diameter = 0;
    /// Height-to-width ratio of the lobules (> 1: palisade-like SAT).
    double lobule_stretch = 1;
    /// The name of the constitutive law (a law of the MaterialRegistry,
    /// which checks it).
    std::string material_model = "linear";
    /// The in-plane stretch of the layer's in vivo state over its
    /// stress-free one (1: none): the imaged geometry is pre-tensioned
    /// (PrestretchedMaterial).
    double prestretch = 1;
    /// The deviatoric Prony series of a visco-elastic layer: the relative
    /// moduli g_i and relaxation times tau_i (s) (empty: elastic); E and nu
    /// are then the instantaneous moduli (ViscoelasticMaterial, which
    /// checks them).
    std::vector<double> relative_moduli;
    std::vector<double> relaxation_times;

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

    std::shared_ptr<FunctionParser<2>> thickness_function;
    /// The thickness if it is a plain number (muParser is slow and takes
    /// a lock per evaluation), NaN otherwise.
    double constant_thickness = std::numeric_limits<double>::quiet_NaN();
  };

  /**
   * The ordered layers, top (skin, z = 0) to bottom. Layer i occupies
   * -depth_{i+1}(x, y) <= z <= -depth_i(x, y) with depth_0 = 0.
   *
   * The set of subsections is decided by the prm file itself (the entry
   * "Layer stack/Layers"), so parsing happens in two passes: first only the
   * list is read (add_layer_list()), then one subsection per layer is
   * declared (add_parameters()) and the file is parsed strictly.
   */
  class LayerStack
  {
  public:
    /// Declares "Layer stack/Layers" and the factor of the skin, bound to
    /// this stack (first, tolerant pass).
    void
    add_layer_list(ParameterHandler &prm);

    /// The layer names, as read by the first pass.
    std::vector<std::string>
    layer_names() const;

    /// Declares the list and one subsection per name (second pass), bound
    /// to layers whose defaults depend on the name (a kind's name gets that
    /// kind's thickness and modulus).
    void
    add_parameters(ParameterHandler               &prm,
                   const std::vector<std::string> &layer_names);

    /// Validates the parsed layers and derives what follows from them
    /// (kinds, thickness functions, effective moduli); throws with a clear
    /// message naming the parameter.
    void
    finalise();

    /// Thinnest and thickest layer accepted anywhere, mm: thinner layers
    /// are below any tissue's scale and make the system singular, thicker
    /// ones are no skin.
    static constexpr double min_thickness = 1e-3, max_thickness = 1e4;

    /// Smallest Poisson's ratio accepted (the bulk modulus vanishes at -1)
    /// and the largest ratio of two layers' Young's moduli.
    static constexpr double min_poisson_ratio    = -0.9,
                            max_modulus_contrast = 1e6;

    /**
     * Checks that every thickness is finite and within [min_thickness,
     * max_thickness] over the patch [-Lx/2, Lx/2] x [-Ly/2, Ly/2], sampled
     * on a regular grid (before the mesh exists; the background mesh checks
     * its own vertices with check_thickness_at()).
     */
    void
    check_thickness_positive(const double Lx, const double Ly) const;

    /// The same check at one point (x, y); throws naming the layer.
    void
    check_thickness_at(const double x, const double y) const;

    /**
     * Checks that every thickness is the same at (x, y), (-x, y) and
     * (x, -y) over the patch, sampled on a regular grid: a quarter model
     * (Mesh/Symmetry = quarter) would otherwise answer for the mirror image
     * of its first quadrant. Throws naming the layer and both points.
     */
    void
    check_mirror_symmetric(const double Lx, const double Ly) const;

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

    /// Sets the law of layer @p i by name (tests, benchmarks).
    void
    set_model(const unsigned int i, const std::string &material_model)
    {
      layers[i].material_model = material_model;
    }

    /// Sets the prestretch of layer @p i (tests, benchmarks).
    void
    set_prestretch(const unsigned int i, const double prestretch)
    {
      layers[i].prestretch = prestretch;
    }

    /// Makes layer @p i visco-elastic with the Prony terms
    /// (@p relative_moduli, @p relaxation_times) (tests, benchmarks).
    void
    set_viscoelasticity(const unsigned int         i,
                        const std::vector<double> &relative_moduli,
                        const std::vector<double> &relaxation_times)
    {
      layers[i].relative_moduli  = relative_moduli;
      layers[i].relaxation_times = relaxation_times;
    }

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
    /// Parses the thickness expression of @p layer; throws naming it.
    static void
    initialise_thickness(Layer &layer);

    /// Throws, naming the layer, unless its thickness at (x, y) is in range.
    static void
    check_thickness(const Layer &layer, const double x, const double y);

    std::string        layer_list = "skin, SAT, SM, DAT, deep";
    std::vector<Layer> layers;
    double             skin_modulus_factor = 1.;
  };
} // namespace ssc

#endif
