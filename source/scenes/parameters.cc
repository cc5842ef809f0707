#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <ssc/base/input_file.h>
#include <ssc/mechanics/elasticity_parameters.h>
#include <ssc/microstructure/ligaments.h>
#include <ssc/scenes/model_size.h>
#include <ssc/scenes/parameters.h>

namespace ssc
{
  namespace
  {
    /// A parameter file larger than this is no parameter file.
    constexpr std::uintmax_t max_parameter_file_bytes = 16u << 20;

    /// Applies one "Section/Subsection/Name=value" override to @p prm.
    void
    apply_override(ParameterHandler &prm, const std::string &text)
    {
      const auto equal = text.find('=');
      AssertThrow(equal != std::string::npos,
                  ExcMessage("-s '" + text +
                             "': expected \"Section/Name=value\"."));
      const std::string path  = Utilities::trim(text.substr(0, equal));
      const std::string value = Utilities::trim(text.substr(equal + 1));
      const std::vector<std::string> parts =
        Utilities::split_string_list(path, '/');
      AssertThrow(!parts.empty() && !parts.back().empty(),
                  ExcMessage("-s '" + text + "': no parameter name."));
      unsigned int depth = 0;
      std::string  problem;
      try
        {
          for (; depth + 1 < parts.size(); ++depth)
            prm.enter_subsection(parts[depth]);
          prm.set(parts.back(), value);
        }
      catch (const ParameterHandler::ExcEntryUndeclared &)
        {
          problem = "there is no parameter '" + path +
                    "' (see ssc --print-parameters).";
        }
      catch (const ParameterHandler::ExcValueDoesNotMatchPattern &e)
        {
          std::ostringstream info;
          e.print_info(info);
          problem = "the value does not match the pattern of '" + path +
                    "': " + info.str();
        }
      for (unsigned int d = 0; d < depth; ++d)
        prm.leave_subsection();
      AssertThrow(problem.empty(), ExcMessage("-s '" + text + "': " + problem));
    }
  } // namespace


  void
  parse_with_includes(ParameterHandler  &prm,
                      const std::string &file,
                      const bool         skip_undefined,
                      const unsigned int depth,
                      unsigned int      &n_files)
  {
    AssertThrow(depth < 16,
                ExcMessage("'include' statements nested more than 16 deep "
                           "(does " +
                           file + " include itself?)."));
    // each file may include others several times: bound the total, or a
    // fan-out of a few files would take forever
    AssertThrow(++n_files <= 1000,
                ExcMessage("More than 1000 parameter files read through "
                           "'include' statements (last: " +
                           file +
                           "): does a file include the same files "
                           "repeatedly?"));
    std::ifstream input(file);
    AssertThrow(input,
                ExcMessage("Cannot open the parameter file '" + file + "'."));
    std::vector<std::string> lines;
    for (std::string line; std::getline(input, line);)
      lines.push_back(line);

    // Split at the include lines; each piece is parsed with every other line
    // blanked, so that deal.II's messages keep this file's line numbers.
    const auto parse_piece = [&](const unsigned int begin,
                                 const unsigned int end) {
      std::ostringstream piece;
      for (unsigned int i = 0; i < lines.size(); ++i)
        piece << (i >= begin && i < end ? lines[i] : std::string()) << '\n';
      std::istringstream stream(piece.str());
      prm.parse_input(stream, file, "", skip_undefined);
    };
    int          level = 0;
    unsigned int begin = 0;
    for (unsigned int i = 0; i < lines.size(); ++i)
      {
        std::string first;
        std::istringstream(lines[i]) >> first;
        if (first == "subsection")
          ++level;
        else if (first == "end")
          --level;
        else if (first == "include" || first == "INCLUDE")
          {
            AssertThrow(level == 0,
                        ExcMessage(file + ", line " + std::to_string(i + 1) +
                                   ": 'include' is allowed only outside "
                                   "subsections."));
            parse_piece(begin, i);
            begin = i + 1;
            std::filesystem::path included(
              Utilities::trim(Utilities::trim(lines[i]).substr(first.size())));
            if (included.is_relative())
              included = std::filesystem::path(file).parent_path() / included;
            check_input_file(included.string(),
                             file + ", line " + std::to_string(i + 1) +
                               ": the included parameter file '" +
                               included.string() + "'",
                             "a .prm file",
                             max_parameter_file_bytes);
            parse_with_includes(
              prm, included.string(), skip_undefined, depth + 1, n_files);
          }
      }
    parse_piece(begin, lines.size());
  }


  void
  Parameters::add_parameters(ParameterHandler               &handler,
                             const std::vector<std::string> &layer_names)
  {
    run.add_parameters(handler);
    layers.add_parameters(handler, layer_names);
    materials.add_parameters(handler, layer_names);
    mesh.add_parameters(handler);
    elasticity.add_parameters(handler);
    punch.add_parameters(handler);
    growth.add_parameters(handler);
    incision.add_parameters(handler);
    time.add_parameters(handler);
    microstructure.add_parameters(handler);
    embedded.add_parameters(handler);
    newton.add_parameters(handler);
    limits.add_parameters(handler);
    identification.add_parameters(handler);
  }


  void
  Parameters::read(const std::string              &file,
                   const std::vector<std::string> &overrides)
  {
    if (!file.empty())
      check_input_file(file,
                       "The parameter file '" + file + "'",
                       "a .prm file",
                       max_parameter_file_bytes);

    // First pass: only the layer list matters, everything else is skipped.
    std::vector<std::string> names;
    {
      ParameterHandler first;
      LayerStack       list;
      list.add_layer_list(first);
      if (!file.empty())
        parse_with_includes(first, file, /*skip_undefined=*/true);
      for (const auto &o : overrides)
        try
          {
            apply_override(first, o);
          }
        catch (...)
          {
            // reported by the strict second pass
          }
      names = list.layer_names();
    }

    // Second pass: strict, into members that start from their defaults.
    prm.clear();
    run            = RunParameters();
    layers         = LayerStack();
    mesh           = MeshParameters();
    elasticity     = ElasticityParameters();
    punch          = PunchParameters();
    growth         = GrowthParameters();
    incision       = IncisionParameters();
    time           = TimeParameters();
    microstructure = MicrostructureParameters();
    embedded       = EmbeddedParameters();
    newton         = NewtonParameters();
    limits         = ResourceLimits();
    identification = IdentificationParameters();
    materials.clear();
    add_parameters(prm, names);
    if (!file.empty())
      parse_with_includes(prm, file, /*skip_undefined=*/false);
    for (const auto &o : overrides)
      apply_override(prm, o);
    parameter_file    = file;
    applied_overrides = overrides;
    finalise();
    check_consistency();
  }


  void
  Parameters::finalise()
  {
    run.check();
    layers.finalise();
    materials.check(layers);
    mesh.check();
    elasticity.check();
    punch.check();
    growth.check();
    incision.check();
    time.check();
    microstructure.check();
    embedded.check();
    newton.check();
    identification.check();
  }


  void
  Parameters::check_consistency() const
  {
    const LayerMaterials layer_laws(layers, materials);
    layers.check_thickness_positive(mesh.patch_length_x, mesh.patch_length_y);
    check_formulation(layer_laws);
    check_microstructure();
    if (run.scene == SceneKind::indentation)
      check_punch_fits();
    if (run.scene == SceneKind::identification)
      check_identification(layer_laws);
    if (run.scene == SceneKind::incision)
      check_incision(layer_laws);
    check_model_size(*this);
  }


  void
  Parameters::check_incision(const LayerMaterials &layer_laws) const
  {
    const unsigned int deepest =
      layers.index_of(incision.deepest_layer, "Incision/Deepest layer cut");
    AssertThrow(deepest + 1 < layers.n_layers(),
                ExcMessage(
                  "Incision/Deepest layer cut = " + incision.deepest_layer +
                  " cuts through every layer, and the patch would "
                  "fall apart: the cut has to end above the "
                  "bottom layer."));
    const bool disc = incision.shape == Incision::Shape::disc;
    AssertThrow(mesh.layout == MeshLayout::box &&
                  mesh.symmetry == MeshSymmetry::none &&
                  std::abs(mesh.fitted_circle_radius -
                           (disc ? incision.length / 2 : 0.)) <=
                    1e-12 * incision.length,
                ExcMessage(disc ? "Incision/Shape = disc removes the disc "
                                  "whose edge the mesh lines follow: "
                                  "Mesh/Layout = box, Symmetry = none, "
                                  "Fitted circle radius = half of "
                                  "Incision/Length." :
                                  "The incision scene cuts along the "
                                  "mesh lines of the whole patch (an "
                                  "ellipse's own map bends them onto its "
                                  "rim): Mesh/Layout = box, Symmetry = "
                                  "none, no Fitted circle radius."));
    AssertThrow(layer_laws.any_prestretch(),
                ExcMessage("The incision scene opens the wound with the "
                           "skin's pre-tension, but no layer has one: set "
                           "Layer stack/<layer>/Prestretch above 1 (e.g. "
                           "1.2 in the skin)."));
    AssertThrow(elasticity.sides != SideCondition::free,
                ExcMessage("The incision scene needs Elasticity/Sides = "
                           "roller or fixed: the sides hold the skin's "
                           "pre-tension."));
  }


  void
  Parameters::check_formulation(const LayerMaterials &layer_laws) const
  {
    const bool nonlinear = layer_laws.any_finite_strain();
    AssertThrow(mesh.layout != MeshLayout::o_grid ||
                  mesh.o_grid_outer_boundary != OuterBoundary::circle ||
                  elasticity.sides != SideCondition::roller,
                ExcMessage("Elasticity/Sides = roller holds the normal "
                           "displacement of the four sides of a rectangular "
                           "patch; with Mesh/O-grid/Outer boundary = circle "
                           "use Sides = fixed or free."));
    AssertThrow(!embedded.ligament_tension_only || nonlinear,
                ExcMessage("Embedded/Ligaments/Tension only needs Newton's "
                           "method: give at least one layer a nonlinear "
                           "Material model (a finite-strain law)."));
    AssertThrow(embedded.ligament_contraction == 0 || nonlinear,
                ExcMessage("Embedded/Ligaments/Contraction needs finite "
                           "strain: give the layers a nonlinear Material "
                           "model (a finite-strain law)."));
    AssertThrow(!embedded.septum_tension_field || nonlinear,
                ExcMessage("Embedded/Septa/Tension field needs Newton's "
                           "method: give at least one layer a nonlinear "
                           "Material model (a finite-strain law)."));
    AssertThrow(elasticity.volumetric_stabilisation == 0 ||
                  (nonlinear && elasticity.n_pressure_modes() > 0 &&
                   elasticity.formulation != Formulation::enhanced),
                ExcMessage("Elasticity/Volumetric stabilisation acts on the "
                           "projected dilatation of finite-strain layers: it "
                           "needs Formulation = mixed or mean dilatation and "
                           "a nonlinear Material model."));
    if (elasticity.formulation == Formulation::enhanced)
      for (unsigned int l = 0; l < layers.n_layers(); ++l)
        AssertThrow(layer_laws[l].kinematics() == Kinematics::small_strain,
                    ExcMessage("Elasticity/Formulation = enhanced is for the "
                               "linear material model only, but Layer "
                               "stack/" +
                               layers.layer(l).name + "/Material model = " +
                               layers.layer(l).material_model +
                               ": use mixed or mean dilatation with "
                               "finite-strain layers."));
    if (mesh.symmetry == MeshSymmetry::quarter)
      AssertThrow(mesh.layout == MeshLayout::box &&
                    (run.scene == SceneKind::indentation ||
                     run.scene == SceneKind::identification) &&
                    !microstructure.lobules && !microstructure.ligaments &&
                    !punch.edge_contact,
                  ExcMessage("Mesh/Symmetry = quarter needs a problem "
                             "symmetric about the planes x = 0 and y = 0: "
                             "the indentation (or identification) scene on "
                             "the box layout, "
                             "without Microstructure/Lobules or Ligaments "
                             "and without Punch/Edge contact."));
    if (mesh.symmetry == MeshSymmetry::quarter)
      layers.check_mirror_symmetric(mesh.patch_length_x, mesh.patch_length_y);
    AssertThrow(punch.contact != PunchContact::friction || nonlinear,
                ExcMessage("Punch/Contact = friction is nonlinear: it needs "
                           "Newton's method, so give at least one layer a "
                           "nonlinear Material model (a finite-strain "
                           "law)."));
    AssertThrow(punch.depth_error_estimate !=
                    DepthErrorEstimate::enriched_degree ||
                  (run.scene == SceneKind::indentation &&
                   punch.control == PunchControl::force &&
                   elasticity.degree == 1),
                ExcMessage("Punch/Depth error estimate = enriched degree "
                           "estimates the depth at the prescribed forces of "
                           "a Q1 indentation by a step of Q2-P0: it needs "
                           "Run/Scene = indentation, Punch/Control = force "
                           "and Elasticity/Degree = 1."));
    AssertThrow(punch.depth_error_estimate !=
                    DepthErrorEstimate::coarser_mesh ||
                  (run.scene == SceneKind::indentation &&
                   punch.control == PunchControl::force &&
                   mesh.global_refinements >= 1),
                ExcMessage("Punch/Depth error estimate = coarser mesh "
                           "estimates the depth at the prescribed forces of "
                           "an indentation from a second path on the mesh "
                           "with one global refinement fewer: it needs "
                           "Run/Scene = indentation, Punch/Control = force "
                           "and Mesh/Global refinements >= 1."));
    AssertThrow(!time.enabled() ||
                  (run.scene == SceneKind::indentation && nonlinear &&
                   punch.depth_error_estimate == DepthErrorEstimate::none),
                ExcMessage("Time/Loading history = " +
                           std::string(to_string(time.history)) +
                           " moves the indentation scene's punch in time: "
                           "it needs Run/Scene = indentation, a finite-strain "
                           "law in some layer (visco-elastic layers are "
                           "finite strain) and no Punch/Depth error "
                           "estimate (which follows the quasi-static "
                           "path)."));
    AssertThrow(!punch.edge_contact || nonlinear,
                ExcMessage("Punch/Edge contact needs Newton's method: give "
                           "at least one layer a nonlinear Material model "
                           "(a finite-strain law)."));
  }


  void
  Parameters::check_microstructure() const
  {
    if (microstructure.lobules || microstructure.ligaments)
      {
        // throws unless the region overlaps the patch
        const BoundingBox<2> rectangle =
          microstructure.region.bounding_rectangle(mesh.patch_length_x,
                                                   mesh.patch_length_y);
        if (microstructure.lobules)
          {
            bool any = false;
            for (unsigned int l = 0; l < layers.n_layers(); ++l)
              any = any || (layers.layer(l).is_adipose() &&
                            layers.layer(l).lobule_diameter > 0);
            AssertThrow(any,
                        ExcMessage("Microstructure/Lobules is on, but no "
                                   "layer of kind SAT or DAT has a positive "
                                   "Lobule diameter."));
          }
        // checks the target layer and the density over the region
        if (microstructure.ligaments)
          place_ligaments(layers, rectangle, microstructure);
      }
    if (run.scene == SceneKind::growth)
      for (const std::string &name : growth.layers)
        layers.index_of(name, "Growth/Layers"); // throws if unknown
  }


  void
  Parameters::check_punch_fits() const
  {
    const double smallest = std::min(mesh.patch_length_x, mesh.patch_length_y);
    std::ostringstream msg;
    if (punch.shape == PunchShape::circle)
      {
        msg << "Punch/Radius = " << punch.radius << " mm: the punch (diameter "
            << 2 * punch.radius << " mm) does not fit in the patch ("
            << mesh.patch_length_x << " x " << mesh.patch_length_y
            << " mm). Enlarge Mesh/Patch length x and y or shrink the "
               "punch.";
        AssertThrow(2 * punch.radius < smallest, ExcMessage(msg.str()));
      }
    else
      {
        // a face as large as the patch is allowed: confined compression
        msg << "Punch/Length x Width = " << punch.length << " x " << punch.width
            << " mm does not fit in the patch (" << mesh.patch_length_x << " x "
            << mesh.patch_length_y
            << " mm). Enlarge Mesh/Patch length x and y or shrink the "
               "punch.";
        AssertThrow(punch.length <= mesh.patch_length_x * (1. + 1e-12) &&
                      punch.width <= mesh.patch_length_y * (1. + 1e-12),
                    ExcMessage(msg.str()));
        AssertThrow(mesh.layout == MeshLayout::box,
                    ExcMessage("Punch/Shape = rectangle needs Mesh/Layout "
                               "= box (the o-grid follows a circle)."));
      }
    const double stack = layers.depth_of_interface(layers.n_layers(), 0, 0);
    std::ostringstream depth;
    depth << "Punch/Depth = " << punch.depth
          << " mm reaches through the whole layer stack (" << stack
          << " mm at the patch centre): the punch must stay inside the "
             "body.";
    AssertThrow(punch.control == PunchControl::force || punch.depth < stack,
                ExcMessage(depth.str()));
  }


  void
  Parameters::check_identification(const LayerMaterials &layer_laws) const
  {
    AssertThrow(!identification.data_file.empty(),
                ExcMessage("Run/Scene = identification needs "
                           "Identification/Data file (the in vivo "
                           "trials, e.g. data/multis/"
                           "indentation_trials.csv)."));
    // the forward model is the trial's skin, fat and muscle, linear:
    // one solve per trial and moduli, homogeneous of degree one in them
    AssertThrow(layers.n_layers() == 3,
                ExcMessage("Run/Scene = identification: the Layer stack "
                           "must list exactly three layers, skin, fat "
                           "and muscle from the top (the data's), not " +
                           std::to_string(layers.n_layers()) + "."));
    for (unsigned int l = 0; l < 3; ++l)
      AssertThrow(layer_laws[l].kinematics() == Kinematics::small_strain,
                  ExcMessage("Run/Scene = identification fits the moduli "
                             "of a linear model (one solve per trial "
                             "and moduli): set Layer stack/" +
                             layers.layer(l).name +
                             "/Material model = linear."));
    AssertThrow(punch.shape == PunchShape::rectangle &&
                  punch.control == PunchControl::force,
                ExcMessage("Run/Scene = identification presses the "
                           "trial's flat probe with its force: set "
                           "Punch/Shape = rectangle and Punch/Control = "
                           "force."));
  }


  void
  Parameters::print_defaults(std::ostream &out)
  {
    Parameters       defaults;
    ParameterHandler handler;
    defaults.add_parameters(handler, {"skin", "SAT", "SM", "DAT", "deep"});
    handler.print_parameters(out, ParameterHandler::PRM);
  }


  void
  Parameters::print_used(std::ostream &out) const
  {
    prm.print_parameters(out, ParameterHandler::PRM);
  }
} // namespace ssc
