#include <deal.II/base/exceptions.h>

#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <set>
#include <sstream>
#include <utility>

#include <ssc/base/collective_error.h>
#include <ssc/mesh/background_mesh.h>
#include <ssc/mesh/o_grid.h>

namespace ssc
{
  namespace
  {
    /**
     * Sizes that continue a geometric sequence over a segment of @p length:
     * from @p size, each @p ratio times the one before but at most @p cap,
     * until they reach @p length (to @p tolerance); the last one is dropped
     * if it overshoots by more than half of itself. @p size becomes the
     * sequence's next size. The caller scales the sizes to the segment.
     */
    std::vector<double>
    continue_graded(double      &size,
                    const double ratio,
                    const double cap,
                    const double length,
                    const double tolerance)
    {
      std::vector<double> steps;
      double              sum = 0;
      while (sum < length - tolerance)
        {
          steps.push_back(size);
          sum += size;
          size = std::min(cap, size * ratio);
        }
      if (steps.size() > 1 && sum - length > 0.5 * steps.back())
        {
          size = steps.back();
          steps.pop_back();
        }
      return steps;
    }
  } // namespace


  BackgroundMesh::BackgroundMesh(const LayerStack     &layers,
                                 const MeshParameters &parameters,
                                 const MPI_Comm        mpi_communicator,
                                 const ResourceLimits &limits,
                                 const bool            multigrid_levels,
                                 const Incision       &incision)
    : layers(layers)
    , parameters(parameters)
    , limits(limits)
    , multigrid_levels(multigrid_levels)
    , incision(incision)
    // multigrid needs the level difference limited at vertices; the other
    // meshes keep deal.II's default smoothing (copy_triangulation() in
    // build() takes the coarse mesh's, which is this one)
    , tria(mpi_communicator,
           multigrid_levels ?
             Triangulation<3>::limit_level_difference_at_vertices :
             Triangulation<3>::none,
           multigrid_levels ?
             parallel::distributed::Triangulation<
               3>::construct_multigrid_hierarchy :
             parallel::distributed::Triangulation<3>::default_setting)
  {}


  std::vector<double>
  BackgroundMesh::graded_steps(const double L,
                               const double h,
                               const double core_half_width,
                               const double ratio,
                               const double edge_size)
  {
    const double half = L / 2;
    if (ratio <= 1. + 1e-12 || core_half_width >= half)
      {
        const unsigned int n = std::max(1., std::ceil(L / h - 1e-10));
        return std::vector<double>(n, L / n);
      }
    // one half, from the centre outwards
    std::vector<double> half_steps;
    if (edge_size > 0)
      {
        // from the core's edge inwards: growing from edge_size, at most h,
        // scaled to the core
        double size = edge_size;
        half_steps =
          continue_graded(size, ratio, h, core_half_width, 1e-10 * L);
        const double sum =
          std::accumulate(half_steps.begin(), half_steps.end(), 0.);
        for (double &step : half_steps)
          step *= core_half_width / sum;
        std::reverse(half_steps.begin(), half_steps.end());
      }
    else
      {
        const unsigned int n_core =
          std::max(1., std::ceil(core_half_width / h - 1e-10));
        half_steps.assign(n_core, core_half_width / n_core);
      }
    const double        remaining = half - core_half_width;
    std::vector<double> graded;
    double size = edge_size > 0 ? edge_size / ratio : half_steps.back();
    double sum  = 0;
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


  std::vector<double>
  BackgroundMesh::lateral_steps(const MeshParameters &parameters,
                                const unsigned int    direction)
  {
    std::vector<double> steps =
      graded_steps(direction == 0 ? parameters.patch_length_x :
                                    parameters.patch_length_y,
                   parameters.cell_size,
                   parameters.core_half_width_in(direction),
                   parameters.grading_ratio,
                   parameters.core_edge_cell_size);
    if (parameters.symmetry == MeshSymmetry::quarter)
      {
        // the steps are symmetric about the centre; an odd count has a
        // cell across it, which is split in two
        const std::size_t   n = steps.size();
        std::vector<double> half(steps.begin() + n / 2, steps.end());
        if (n % 2 == 1)
          half.front() /= 2;
        steps = half;
      }
    return steps;
  }


  std::vector<double>
  BackgroundMesh::vertical_steps(const LayerStack     &layers,
                                 const MeshParameters &parameters)
  {
    // per layer from the top, then listed from the bottom (zeta =
    // -n_layers) to the top (zeta = 0) in the chart, where each layer has
    // unit height
    std::vector<std::vector<double>> per_layer;
    const bool o_grid              = parameters.layout == MeshLayout::o_grid;
    const bool graded_from_surface = o_grid ?
                                       parameters.o_grid_grade_in_depth :
                                       parameters.core_edge_cell_size > 0;
    // at the surface, and its growth ratio
    double       height = o_grid ? parameters.o_grid_edge_cell_size :
                                   parameters.core_edge_cell_size;
    const double ratio =
      o_grid ? parameters.o_grid_radial_grading : parameters.grading_ratio;
    for (unsigned int l = 0; l < layers.n_layers(); ++l)
      {
        const Layer        &layer = layers.layer(l);
        std::vector<double> h;
        if (graded_from_surface)
          {
            // heights continue the surface's geometric sequence over the
            // layer's thickness at the centre
            h = continue_graded(height,
                                ratio,
                                std::numeric_limits<double>::infinity(),
                                layer.thickness(0, 0),
                                0.);
            if (h.size() < layer.n_cells_across)
              h.assign(layer.n_cells_across, 1.);
          }
        else
          for (unsigned int k = 0; k < layer.n_cells_across; ++k)
            h.push_back(std::pow(layer.grading, k)); // k = 0 at the top
        double sum = 0;
        for (const double step : h)
          sum += step;
        for (double &step : h)
          step /= sum;
        per_layer.push_back(h);
      }
    std::vector<double> z_steps;
    for (auto layer = per_layer.rbegin(); layer != per_layer.rend(); ++layer)
      z_steps.insert(z_steps.end(), layer->rbegin(), layer->rend());
    return z_steps;
  }


  double
  BackgroundMesh::estimated_cells(const LayerStack     &layers,
                                  const MeshParameters &parameters)
  {
    const double across = vertical_steps(layers, parameters).size();
    if (parameters.layout == MeshLayout::o_grid)
      return static_cast<double>(OGrid(parameters).n_cells()) * across *
             std::pow(8., parameters.global_refinements);
    const double lateral =
      static_cast<double>(lateral_steps(parameters, 0).size()) *
      lateral_steps(parameters, 1).size();
    return lateral * across * std::pow(8., parameters.global_refinements);
  }


  void
  BackgroundMesh::build()
  {
    ResourceLimits::require(estimated_cells(layers, parameters),
                            limits.max_cells,
                            "The background mesh's cell count",
                            "Max cells",
                            parameters.coarsening_advice());
    const unsigned int n_layers = layers.n_layers();

    const std::vector<double> z_steps = vertical_steps(layers, parameters);

    Triangulation<3> coarse(tria.get_mesh_smoothing());
    if (parameters.layout == MeshLayout::box)
      {
        const std::vector<std::vector<double>> steps = {
          lateral_steps(parameters, 0), lateral_steps(parameters, 1), z_steps};
        const bool quarter = parameters.symmetry == MeshSymmetry::quarter;
        GridGenerator::subdivided_hyper_rectangle(
          coarse,
          steps,
          Point<3>(quarter ? 0. : -parameters.patch_length_x / 2,
                   quarter ? 0. : -parameters.patch_length_y / 2,
                   -static_cast<double>(n_layers)),
          Point<3>(parameters.patch_length_x / 2,
                   parameters.patch_length_y / 2,
                   0),
          /*colorize=*/true);
      }
    else
      extrude_o_grid(z_steps, coarse);

    for (const auto &cell : coarse.active_cell_iterators())
      cell->set_material_id(std::min<unsigned int>(
        n_layers - 1,
        static_cast<unsigned int>(std::floor(-cell->center()[2]))));
    if (!incision.empty())
      {
        const bool disc = incision.shape == Incision::Shape::disc;
        AssertThrow(parameters.layout == MeshLayout::box &&
                      std::abs(parameters.fitted_circle_radius -
                               (disc ? incision.length / 2 : 0.)) <=
                        1e-12 * incision.length,
                    ExcMessage(disc ?
                                 "An excision needs Mesh/Layout = box with a "
                                 "Fitted circle radius of half the disc's "
                                 "diameter: the mesh lines follow its edge." :
                                 "An incision or an elliptic excision needs "
                                 "Mesh/Layout = box without a Fitted circle "
                                 "radius: it is cut along the box's mesh "
                                 "lines (which the ellipse's own map bends "
                                 "onto its rim)."));
        cut_coarse_mesh(coarse, incision, n_layers, "Incision/Length");
      }

    // the o-grid's lateral coordinates are physical already; an ellipse's
    // rim is fitted by the map of its own semi-axes
    const std::array<double, 2> fitted =
      incision.shape == Incision::Shape::ellipse ?
        incision.semi_axes() :
        std::array<double, 2>{
          {parameters.fitted_circle_radius, parameters.fitted_circle_radius}};
    const LayerManifold layer_map(layers,
                                  parameters.layout == MeshLayout::box ?
                                    DiskFittingMap(fitted[0], fitted[1]) :
                                    DiskFittingMap());
    GridTools::transform(
      [&layer_map](const Point<3> &p) { return layer_map.push_forward(p); },
      coarse);
    coarse.set_all_manifold_ids(0);
    if (parameters.layout == MeshLayout::o_grid)
      set_polar_manifold_ids(coarse);
    // the same on every rank: the coarse mesh is whole on each
    for (const Point<3> &p : coarse.get_vertices())
      layers.check_thickness_at(p[0], p[1]);

    if (multigrid_levels)
      order_columns(coarse);
    tria.copy_triangulation(coarse);
    tria.set_manifold(0, layer_map);
    if (parameters.layout == MeshLayout::o_grid)
      tria.set_manifold(1, LayerManifold::polar(layers));
    tria.refine_global(parameters.global_refinements);
    refine_region_of_interest();
    check_thickness_at_vertices();
    if (parameters.fitted_circle_radius > 0)
      check_fitted_circle();
  }


  void
  BackgroundMesh::order_columns(Triangulation<3> &coarse)
  {
    auto [vertices, cells, faces] =
      GridTools::get_coarse_mesh_description(coarse);
    std::vector<Point<3>> centres;
    for (const auto &cell : cells)
      {
        Point<3> centre;
        for (const unsigned int v : cell.vertices)
          centre += vertices[v] / static_cast<double>(cell.vertices.size());
        centres.push_back(centre);
      }
    // lateral positions equal to a thousandth of the smallest cell
    const double tolerance = 1e-3 * GridTools::minimal_cell_diameter(coarse);
    std::vector<unsigned int> order(cells.size());
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(
      order.begin(), order.end(), [&](const auto a, const auto b) {
        for (const unsigned int d : {0u, 1u})
          if (std::abs(centres[a][d] - centres[b][d]) > tolerance)
            return centres[a][d] < centres[b][d];
        return centres[a][2] < centres[b][2];
      });
    std::vector<CellData<3>> ordered;
    for (const unsigned int k : order)
      ordered.push_back(cells[k]);
    const auto smoothing = coarse.get_mesh_smoothing();
    coarse.clear();
    coarse.set_mesh_smoothing(smoothing);
    coarse.create_triangulation(vertices, ordered, faces);
  }


  void
  BackgroundMesh::extrude_o_grid(const std::vector<double> &z_steps,
                                 Triangulation<3>          &coarse) const
  {
    Triangulation<2> lateral;
    OGrid(parameters).make(lateral);
    std::vector<double> slices{-static_cast<double>(layers.n_layers())};
    for (const double dz : z_steps)
      slices.push_back(slices.back() + dz);
    slices.back() = 0;
    GridGenerator::extrude_triangulation(lateral, slices, coarse);

    // boundary ids as the box's colorized ones: the lateral faces by the
    // side of the patch their centre is closest to
    const double hx = parameters.patch_length_x / 2,
                 hy = parameters.patch_length_y / 2;
    for (const auto &face : coarse.active_face_iterators())
      if (face->at_boundary())
        {
          const Point<3> c = face->center();
          if (std::abs(c[2]) < 1e-9)
            face->set_boundary_id(BoundaryId::top);
          else if (std::abs(c[2] - slices.front()) < 1e-9)
            face->set_boundary_id(BoundaryId::bottom);
          else if (std::abs(c[0]) / hx >= std::abs(c[1]) / hy)
            face->set_boundary_id(c[0] < 0 ? BoundaryId::x_min :
                                             BoundaryId::x_max);
          else
            face->set_boundary_id(c[1] < 0 ? BoundaryId::y_min :
                                             BoundaryId::y_max);
        }
  }


  void
  BackgroundMesh::set_polar_manifold_ids(Triangulation<3> &coarse) const
  {
    const OGrid  o_grid(parameters);
    const double r_min    = o_grid.inner_circle_radius() * (1. - 1e-9),
                 r_max    = o_grid.outer_circle_radius() * (1. + 1e-9);
    const auto on_circles = [r_min, r_max](const auto &object) {
      for (const unsigned int v : object->vertex_indices())
        {
          const double r =
            std::hypot(object->vertex(v)[0], object->vertex(v)[1]);
          if (r < r_min || r > r_max)
            return false;
        }
      return true;
    };
    for (const auto &cell : coarse.active_cell_iterators())
      {
        if (on_circles(cell))
          cell->set_manifold_id(1);
        for (const auto &face : cell->face_iterators())
          if (on_circles(face))
            face->set_manifold_id(1);
        for (const unsigned int l : cell->line_indices())
          if (on_circles(cell->line(l)))
            cell->line(l)->set_manifold_id(1);
      }
  }


  void
  BackgroundMesh::check_thickness_at_vertices() const
  {
    run_collectively(
      [this]() {
        // the thickness depends on (x, y) only: each column of vertices
        // once, and the edge midpoints and centres that a curved (Q2)
        // mapping also places on the layer map
        std::set<std::pair<double, double>> columns;
        for (const auto &cell : tria.active_cell_iterators())
          if (cell->is_locally_owned())
            {
              for (const unsigned int v : cell->vertex_indices())
                columns.emplace(cell->vertex(v)[0], cell->vertex(v)[1]);
              for (const unsigned int l : cell->line_indices())
                columns.emplace(cell->line(l)->center()[0],
                                cell->line(l)->center()[1]);
              columns.emplace(cell->center()[0], cell->center()[1]);
            }
        for (const auto &[x, y] : columns)
          layers.check_thickness_at(x, y);
      },
      tria.get_communicator());
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
    if (found >= (parameters.symmetry == MeshSymmetry::quarter ? 3 : 8))
      return;
    // the core's cells are Core half width / ceil(Core half width / Cell
    // size) wide, which may differ from Cell size
    const double core = parameters.core_half_width;
    const double h =
      core / std::max(1., std::ceil(core / parameters.cell_size - 1e-10));
    std::ostringstream message;
    message << "Mesh/Fitted circle radius = " << a
            << " mm does not lie on a mesh line of the refined mesh: the "
               "core cells are "
            << h << " mm wide (Core half width " << core << " mm in "
            << std::round(core / h) << " cells of at most Cell size "
            << parameters.cell_size << " mm), "
            << h / std::pow(2., parameters.global_refinements)
            << " mm after the global refinements; choose a radius that is a "
               "multiple of that, or a Cell size and Core half width whose "
               "mesh lines pass through it.";
    AssertThrow(false, ExcMessage(message.str()));
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
        // each refined cell becomes eight (the 2:1 balance adds a few more)
        unsigned int flagged = 0;
        for (const auto &cell : tria.active_cell_iterators())
          flagged += cell->is_locally_owned() && cell->refine_flag_set();
        ResourceLimits::require(
          static_cast<double>(tria.n_global_active_cells()) +
            7. * Utilities::MPI::sum(flagged, tria.get_communicator()),
          limits.max_cells,
          "The background mesh's cell count after local refinement " +
            std::to_string(step + 1),
          "Max cells",
          "use fewer Mesh/Region of interest/Local refinements, a smaller "
          "Width or Shrink factor");
        tria.execute_coarsening_and_refinement();
        width *= parameters.roi_shrink;
      }
  }
} // namespace ssc
