#include <deal.II/base/exceptions.h>

#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria.h>

#include <ssc/background_mesh.h>

#include <cmath>

namespace ssc
{
  void
  MeshParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Mesh");
    prm.declare_entry("Patch length x",
                      "40",
                      Patterns::Double(0),
                      "Lateral extent of the patch in x, mm, centred at 0.");
    prm.declare_entry("Patch length y",
                      "40",
                      Patterns::Double(0),
                      "Lateral extent of the patch in y, mm, centred at 0.");
    prm.declare_entry("Cell size",
                      "2",
                      Patterns::Double(0),
                      "Lateral size of the background hexahedra in the core "
                      "of the patch on the coarsest mesh, mm (Herlin et al. "
                      "2014 used about 2 mm).");
    prm.declare_entry("Core half width",
                      "10",
                      Patterns::Double(0),
                      "Half width (mm) of the central square in which cells "
                      "have the lateral 'Cell size'; outside it they grow by "
                      "'Grading ratio' per cell towards the patch edge.");
    prm.declare_entry("Grading ratio",
                      "1",
                      Patterns::Double(1, 3),
                      "Growth ratio of the lateral cell size outside the "
                      "core (1 = uniform mesh).");
    prm.declare_entry("Global refinements",
                      "0",
                      Patterns::Integer(0, 8),
                      "Uniform refinements of the coarse mesh (each halves "
                      "every cell size, in the layers too).");
    prm.declare_entry(
      "Fitted circle radius",
      "0",
      Patterns::Double(0),
      "Radius a (mm) of a circle around the patch centre that mesh lines "
      "follow exactly, e.g. the edge of a punch (0: none). The square "
      "|x|, |y| <= a of the Cartesian mesh is mapped onto the disk r <= a and "
      "blended back to the undistorted mesh at |x|, |y| = 2a, so a must be "
      "on a mesh line of the refined mesh (a multiple of the core cell size "
      "after refinement, measured from the patch centre).");
    prm.enter_subsection("Region of interest");
    prm.declare_entry("Ring radius",
                      "0",
                      Patterns::Double(0),
                      "Radius (mm) of the ring around the patch centre, at "
                      "the skin surface, towards which the mesh is refined "
                      "(the edge of a punch, say); 0 refines towards the "
                      "centre line instead.");
    prm.declare_entry("Width",
                      "5",
                      Patterns::Double(0),
                      "Lateral and vertical reach (mm) of the refined region "
                      "around the ring (or the centre line).");
    prm.declare_entry("Shrink factor",
                      "1",
                      Patterns::Double(0.1, 1),
                      "The width is multiplied by this factor after each "
                      "local refinement (1: the same region every time; 0.5: "
                      "geometric refinement towards a singular edge).");
    prm.declare_entry("Local refinements",
                      "0",
                      Patterns::Integer(0, 20),
                      "Number of local refinements of the cells touching the "
                      "region (hanging nodes are constrained).");
    prm.leave_subsection();
    prm.leave_subsection();
  }


  void
  MeshParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Mesh");
    patch_length_x       = prm.get_double("Patch length x");
    patch_length_y       = prm.get_double("Patch length y");
    cell_size            = prm.get_double("Cell size");
    core_half_width      = prm.get_double("Core half width");
    grading_ratio        = prm.get_double("Grading ratio");
    global_refinements   = prm.get_integer("Global refinements");
    fitted_circle_radius = prm.get_double("Fitted circle radius");
    prm.enter_subsection("Region of interest");
    roi_radius        = prm.get_double("Ring radius");
    roi_width         = prm.get_double("Width");
    roi_shrink        = prm.get_double("Shrink factor");
    local_refinements = prm.get_integer("Local refinements");
    prm.leave_subsection();
    prm.leave_subsection();

    AssertThrow(patch_length_x > 0 && patch_length_y > 0,
                ExcMessage("Mesh/Patch length x and y must be positive (mm)."));
    AssertThrow(cell_size > 0 &&
                  cell_size <= std::max(patch_length_x, patch_length_y),
                ExcMessage("Mesh/Cell size must be positive and not larger "
                           "than the patch."));
    const double n_cells_estimate = std::ceil(patch_length_x / cell_size) *
                                    std::ceil(patch_length_y / cell_size) *
                                    std::pow(8., global_refinements);
    AssertThrow(n_cells_estimate < 5e7,
                ExcMessage("Mesh/Cell size and Global refinements ask for "
                           "more than 5e7 cells in one layer; this machine "
                           "cannot hold that. Use a larger cell size, fewer "
                           "refinements or grading."));
    AssertThrow(4 * fitted_circle_radius <
                  std::min(patch_length_x, patch_length_y),
                ExcMessage("Mesh/Fitted circle radius: the fitted circle "
                           "and its blending zone (twice the radius) must "
                           "lie inside the patch."));
  }


  BackgroundMesh::BackgroundMesh(const LayerStack     &layers,
                                 const MeshParameters &parameters,
                                 const MPI_Comm        mpi_communicator)
    : layers(layers)
    , parameters(parameters)
    , tria(mpi_communicator,
           Triangulation<3>::limit_level_difference_at_vertices)
  {}


  std::vector<double>
  BackgroundMesh::graded_steps(const double L,
                               const double h,
                               const double core_half_width,
                               const double ratio)
  {
    const double half = L / 2;
    if (ratio <= 1. + 1e-12 || core_half_width >= half)
      {
        const unsigned int n = std::max(1., std::ceil(L / h - 1e-10));
        return std::vector<double>(n, L / n);
      }
    // one half, from the centre outwards
    const unsigned int n_core =
      std::max(1., std::ceil(core_half_width / h - 1e-10));
    std::vector<double> half_steps(n_core, core_half_width / n_core);
    const double        remaining = half - core_half_width;
    std::vector<double> graded;
    double              size = core_half_width / n_core, sum = 0;
    while (sum < remaining - 1e-10 * L)
      {
        size *= ratio;
        graded.push_back(size);
        sum += size;
      }
    // scale the graded part so that it ends exactly at the patch edge
    for (double &g : graded)
      g *= remaining / sum;
    half_steps.insert(half_steps.end(), graded.begin(), graded.end());

    std::vector<double> steps(half_steps.rbegin(), half_steps.rend());
    steps.insert(steps.end(), half_steps.begin(), half_steps.end());
    return steps;
  }


  void
  BackgroundMesh::build()
  {
    const unsigned int n_layers = layers.n_layers();

    // Vertical steps in the chart (each layer has unit height), listed from
    // the bottom (zeta = -n_layers) to the top (zeta = 0).
    std::vector<double> z_steps;
    for (int l = n_layers - 1; l >= 0; --l)
      {
        const Layer        &layer = layers.layer(l);
        std::vector<double> h(layer.n_cells_across);
        double              sum = 0;
        for (unsigned int k = 0; k < h.size(); ++k)
          sum += (h[k] = std::pow(layer.grading, k)); // k = 0 at the top
        for (auto it = h.rbegin(); it != h.rend(); ++it)
          z_steps.push_back(*it / sum);
      }

    const std::vector<std::vector<double>> steps = {
      graded_steps(parameters.patch_length_x,
                   parameters.cell_size,
                   parameters.core_half_width,
                   parameters.grading_ratio),
      graded_steps(parameters.patch_length_y,
                   parameters.cell_size,
                   parameters.core_half_width,
                   parameters.grading_ratio),
      z_steps};

    Triangulation<3> coarse;
    GridGenerator::subdivided_hyper_rectangle(
      coarse,
      steps,
      Point<3>(-parameters.patch_length_x / 2,
               -parameters.patch_length_y / 2,
               -static_cast<double>(n_layers)),
      Point<3>(parameters.patch_length_x / 2, parameters.patch_length_y / 2, 0),
      /*colorize=*/true);

    for (const auto &cell : coarse.active_cell_iterators())
      cell->set_material_id(std::min<unsigned int>(
        n_layers - 1,
        static_cast<unsigned int>(std::floor(-cell->center()[2]))));

    const LayerManifold layer_map(
      layers, DiskFittingMap(parameters.fitted_circle_radius));
    GridTools::transform(
      [&layer_map](const Point<3> &p) { return layer_map.push_forward(p); },
      coarse);
    coarse.set_all_manifold_ids(0);

    tria.copy_triangulation(coarse);
    tria.set_manifold(0, layer_map);
    tria.refine_global(parameters.global_refinements);
    refine_region_of_interest();
    if (parameters.fitted_circle_radius > 0)
      check_fitted_circle();
  }


  void
  BackgroundMesh::check_fitted_circle() const
  {
    const double a     = parameters.fitted_circle_radius;
    unsigned int found = 0;
    for (const auto &cell : tria.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int v : cell->vertex_indices())
          {
            const Point<3> &p = cell->vertex(v);
            if (std::abs(p[2]) < 1e-12 &&
                std::abs(std::hypot(p[0], p[1]) - a) < 1e-9 * a)
              ++found;
          }
    found = Utilities::MPI::sum(found, tria.get_communicator());
    AssertThrow(found >= 8,
                ExcMessage("Mesh/Fitted circle radius = " + std::to_string(a) +
                           " mm does not lie on a mesh line of the refined "
                           "mesh: choose Cell size, Core half width and the "
                           "refinements so that a is a multiple of the core "
                           "cell size on the refined mesh."));
  }


  void
  BackgroundMesh::refine_region_of_interest()
  {
    double width = parameters.roi_width;
    for (unsigned int step = 0; step < parameters.local_refinements; ++step)
      {
        for (const auto &cell : tria.active_cell_iterators())
          if (cell->is_locally_owned())
            {
              const Point<3> c = cell->center();
              const double   r = std::hypot(c[0], c[1]);
              const double   lateral =
                std::max(0., std::abs(r - parameters.roi_radius) - width);
              const double vertical = std::max(0., -c[2] - width);
              if (std::hypot(lateral, vertical) <= 0.5 * cell->diameter())
                cell->set_refine_flag();
            }
        tria.execute_coarsening_and_refinement();
        width *= parameters.roi_shrink;
      }
  }
} // namespace ssc
