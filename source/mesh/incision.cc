#include <deal.II/base/exceptions.h>

#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <sstream>

#include <ssc/mesh/background_mesh.h>
#include <ssc/mesh/incision.h>

namespace ssc
{
  namespace
  {
    /// The coordinate @p d of the vertex of @p vertices nearest to @p value.
    double
    nearest_vertex_coordinate(const std::vector<Point<3>> &vertices,
                              const unsigned int           d,
                              const double                 value)
    {
      double nearest = std::numeric_limits<double>::infinity();
      for (const Point<3> &p : vertices)
        if (std::abs(p[d] - value) < std::abs(nearest - value))
          nearest = p[d];
      return nearest;
    }


    /// The box's colorized boundary ids by position (@p lower, @p upper
    /// its corners); every other boundary face is the cut's.
    void
    set_boundary_ids(Triangulation<3> &coarse,
                     const Point<3>   &lower,
                     const Point<3>   &upper,
                     const double      tolerance)
    {
      for (const auto &face : coarse.active_face_iterators())
        if (face->at_boundary())
          {
            const Point<3>     c  = face->center();
            types::boundary_id id = BoundaryId::cut;
            for (unsigned int d = 0; d < 3; ++d)
              if (std::abs(c[d] - lower[d]) < tolerance)
                id = 2 * d;
              else if (std::abs(c[d] - upper[d]) < tolerance)
                id = 2 * d + 1;
            face->set_boundary_id(id);
          }
    }


    /// Throws, naming @p message, unless @p value is a vertex plane of
    /// @p vertices across direction @p d.
    void
    check_vertex_plane(const std::vector<Point<3>> &vertices,
                       const unsigned int           d,
                       const double                 value,
                       const double                 tolerance,
                       const std::string           &message)
    {
      const char  *names[3] = {"x", "y", "z"};
      const double nearest  = nearest_vertex_coordinate(vertices, d, value);
      std::ostringstream off_line;
      off_line << message << "but the mesh has no vertex plane " << names[d]
               << " = " << value << " (nearest: " << nearest
               << " mm): the cut runs along mesh lines, through the "
                  "patch centre, and ends on them. Choose a length "
                  "that is an even multiple of the core's cells "
                  "(Mesh/Cell size), or an even number of core cells.";
      AssertThrow(std::abs(nearest - value) < tolerance,
                  ExcMessage(off_line.str()));
    }


    /// The excision: the cells of the cut layers inside the rectangle
    /// |x| < @p semi_axes[0], |y| < @p semi_axes[1] removed.
    void
    remove_excision(Triangulation<3>            &coarse,
                    const std::array<double, 2> &semi_axes,
                    const double                 floor,
                    const double                 tolerance,
                    const std::string           &message)
    {
      const std::vector<Point<3>> &vertices = coarse.get_vertices();
      for (const unsigned int d : {0u, 1u})
        for (const double side : {-semi_axes[d], semi_axes[d]})
          check_vertex_plane(vertices, d, side, tolerance, message);
      std::set<Triangulation<3>::active_cell_iterator> removed;
      for (const auto &cell : coarse.active_cell_iterators())
        {
          const Point<3> c = cell->center();
          if (std::abs(c[0]) < semi_axes[0] && std::abs(c[1]) < semi_axes[1] &&
              c[2] > floor)
            removed.insert(cell);
        }
      Triangulation<3> remaining(coarse.get_mesh_smoothing());
      GridGenerator::create_triangulation_with_removed_cells(coarse,
                                                             removed,
                                                             remaining);
      coarse.clear();
      coarse.copy_triangulation(remaining);
    }
  } // namespace


  void
  cut_coarse_mesh(Triangulation<3>  &coarse,
                  const Incision    &incision,
                  const unsigned int n_layers,
                  const std::string &parameter)
  {
    if (incision.empty())
      return;
    AssertThrow(incision.direction < 2,
                ExcMessage(parameter + ": the cut runs along x or y."));
    AssertThrow(incision.n_cut_layers >= 1 && incision.n_cut_layers <= n_layers,
                ExcMessage(parameter + ": the cut goes through 1 to " +
                           std::to_string(n_layers) + " layers."));
    auto [vertices, cells, faces] =
      GridTools::get_coarse_mesh_description(coarse);
    const unsigned int along  = incision.direction,
                       across = incision.normal_direction();
    const double half         = incision.length / 2;
    const double tolerance    = 1e-6 * GridTools::minimal_cell_diameter(coarse);

    // the patch's extent, for the checks and the boundary ids
    Point<3> lower = vertices.front(), upper = vertices.front();
    for (const Point<3> &p : vertices)
      for (unsigned int d = 0; d < 3; ++d)
        {
          lower[d] = std::min(lower[d], p[d]);
          upper[d] = std::max(upper[d], p[d]);
        }
    const char        *names[2] = {"x", "y"};
    const double       floor    = -static_cast<double>(incision.n_cut_layers);
    std::ostringstream message;
    if (incision.excision())
      {
        const std::array<double, 2> semi_axes = incision.semi_axes();
        message << parameter << ": the "
                << (incision.shape == Incision::Shape::disc ? "disc" :
                                                              "ellipse")
                << " reaches " << semi_axes[0] << " mm along x and "
                << semi_axes[1] << " mm along y from the centre, ";
        for (const unsigned int d : {0u, 1u})
          AssertThrow(-2 * semi_axes[d] > lower[d] + tolerance &&
                        2 * semi_axes[d] < upper[d] - tolerance,
                      ExcMessage(message.str() +
                                 "and the mesh lines that follow its edge "
                                 "blend back to straight ones at twice that, "
                                 "beyond the patch: make it smaller or widen "
                                 "the patch."));
        AssertThrow(incision.shape == Incision::Shape::disc ||
                      (incision.width > 0 && incision.width <= incision.length),
                    ExcMessage(message.str() +
                               "but an ellipse's width (short axis) must be "
                               "positive and at most its length."));
        remove_excision(coarse, semi_axes, floor, tolerance, message.str());
        set_boundary_ids(coarse, lower, upper, tolerance);
        return;
      }

    message << parameter << " = " << incision.length << " mm: the cut along "
            << names[along] << " runs from " << -half << " to " << half
            << " mm, ";
    AssertThrow(-half > lower[along] + tolerance &&
                  half < upper[along] - tolerance,
                ExcMessage(message.str() + "beyond the patch (" +
                           std::to_string(lower[along]) + " to " +
                           std::to_string(upper[along]) +
                           " mm): shorten it or widen the patch."));
    AssertThrow(lower[across] < -tolerance && upper[across] > tolerance,
                ExcMessage(message.str() +
                           "but the patch does not extend to both sides "
                           "of it (a quarter model cannot be cut)."));
    check_vertex_plane(vertices, along, -half, tolerance, message.str());
    check_vertex_plane(vertices, along, half, tolerance, message.str());
    check_vertex_plane(vertices, across, 0., tolerance, message.str());

    // the cut's surface: across = 0, |along| < half, z above the floor of
    // the cut layers (its front, the ends and the floor, stays shared; a
    // cut through every layer has no floor)
    const bool                through = incision.n_cut_layers == n_layers;
    std::vector<unsigned int> copy(vertices.size(),
                                   numbers::invalid_unsigned_int);
    const unsigned int        n_vertices = vertices.size();
    for (unsigned int v = 0; v < n_vertices; ++v)
      {
        const Point<3> p = vertices[v];
        if (std::abs(p[across]) < tolerance &&
            std::abs(p[along]) < half - tolerance &&
            (through || p[2] > floor + tolerance))
          {
            copy[v] = vertices.size();
            vertices.push_back(p);
          }
      }
    for (CellData<3> &cell : cells)
      {
        double centre = 0;
        for (const unsigned int v : cell.vertices)
          centre += vertices[v][across] / cell.vertices.size();
        if (centre > 0)
          for (unsigned int &v : cell.vertices)
            if (copy[v] != numbers::invalid_unsigned_int)
              v = copy[v];
      }

    const auto smoothing = coarse.get_mesh_smoothing();
    coarse.clear();
    coarse.set_mesh_smoothing(smoothing);
    coarse.create_triangulation(vertices, cells, SubCellData());
    set_boundary_ids(coarse, lower, upper, tolerance);
  }
} // namespace ssc
