#include <deal.II/base/exceptions.h>
#include <deal.II/base/numbers.h>

#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria_description.h>

#include <algorithm>
#include <cmath>

#include <ssc/mesh/o_grid.h>

namespace ssc
{
  OGrid::OGrid(const MeshParameters &parameters)
    : parameters(parameters)
    , n_around(parameters.o_grid_cells_around)
  {
    const double a = parameters.fitted_circle_radius;
    const double h = parameters.o_grid_edge_cell_size;
    const double q = parameters.o_grid_radial_grading;
    // the radial size grows away from the circle until it reaches the
    // spacing around (cells about square), never beyond
    const auto radial_step = [this, h, q](const double r, const unsigned k) {
      return std::min(h * std::pow(q, k), 2. * numbers::PI * r / n_around);
    };

    // inwards from the circle, down to half its radius
    std::vector<double> inner{a};
    for (unsigned int k = 0;; ++k)
      {
        const double step = radial_step(inner.back(), k);
        if (inner.back() - step < 0.5 * a)
          break;
        inner.push_back(inner.back() - step);
      }
    core_half_width = 0.5 * inner.back();
    n_inner_blend =
      std::max(1.,
               std::round((inner.back() - core_half_width) /
                          (2. * numbers::PI * inner.back() / n_around)));

    // outwards to the patch's circle, or to 80 % of its half width before
    // the blend to the square
    const double half_width =
      0.5 * std::min(parameters.patch_length_x, parameters.patch_length_y);
    const double last_circle =
      parameters.o_grid_outer_boundary == OuterBoundary::circle ?
        half_width :
        0.8 * half_width;
    AssertThrow(last_circle > a,
                ExcMessage("Mesh/Fitted circle radius must be smaller than "
                           "the o-grid's outermost circle (80 % of half the "
                           "patch length for a square patch)."));
    std::vector<double> outer{a};
    for (unsigned int k = 0; outer.back() < last_circle; ++k)
      outer.push_back(outer.back() + radial_step(outer.back(), k));
    // end exactly at the last circle: drop a last step that overshoots by
    // more than half of it, then scale the steps
    if (outer.size() > 2 && outer.back() - last_circle >
                              0.5 * (outer.back() - outer[outer.size() - 2]))
      outer.pop_back();
    const double scale = (last_circle - a) / (outer.back() - a);
    for (double &r : outer)
      r = a + (r - a) * scale;
    outer.back() = last_circle;

    circle_radii.assign(inner.rbegin(), inner.rend());
    circle_radii.insert(circle_radii.end(), outer.begin() + 1, outer.end());

    n_outer_blend = 0;
    if (parameters.o_grid_outer_boundary == OuterBoundary::square)
      n_outer_blend =
        std::max(1.,
                 std::round((1.15 * half_width - last_circle) /
                            (2. * numbers::PI * last_circle / n_around)));
  }


  unsigned int
  OGrid::n_cells() const
  {
    const unsigned int n_rows =
      n_inner_blend + circle_radii.size() + n_outer_blend;
    return n_around * n_around / 16 + n_around * (n_rows - 1);
  }


  double
  OGrid::angle(const unsigned int j) const
  {
    return -0.25 * numbers::PI + 2. * numbers::PI * j / n_around;
  }


  Point<2>
  OGrid::on_circle(const double r, const unsigned int j) const
  {
    return Point<2>(r * std::cos(angle(j)), r * std::sin(angle(j)));
  }


  Point<2>
  OGrid::on_square(const double half_width, const unsigned int j) const
  {
    const double c = std::cos(angle(j)), s = std::sin(angle(j));
    const double m = std::max(std::abs(c), std::abs(s));
    return Point<2>(half_width * c / m, half_width * s / m);
  }


  Point<2>
  OGrid::on_patch_boundary(const unsigned int j) const
  {
    const double c = std::cos(angle(j)), s = std::sin(angle(j));
    const double m = std::max(std::abs(c), std::abs(s));
    return Point<2>(0.5 * parameters.patch_length_x * c / m,
                    0.5 * parameters.patch_length_y * s / m);
  }


  void
  OGrid::make(Triangulation<2> &tria) const
  {
    std::vector<Point<2>>    vertices;
    std::vector<CellData<2>> cells;

    // the core: a square grid whose boundary vertices are the square's
    // ring vertices (uniform angles: x = s tan(phi))
    const unsigned int m     = n_around / 4;
    const auto         coord = [this, m](const unsigned int i) {
      return core_half_width *
             std::tan(-0.25 * numbers::PI + 0.5 * numbers::PI * i / m);
    };
    for (unsigned int k = 0; k <= m; ++k)
      for (unsigned int i = 0; i <= m; ++i)
        vertices.emplace_back(coord(i), coord(k));
    for (unsigned int k = 0; k < m; ++k)
      for (unsigned int i = 0; i < m; ++i)
        {
          CellData<2> cell;
          cell.vertices = {k * (m + 1) + i,
                           k * (m + 1) + i + 1,
                           (k + 1) * (m + 1) + i,
                           (k + 1) * (m + 1) + i + 1};
          cells.push_back(cell);
        }

    // the rows of ring vertices, from the core's square outwards
    std::vector<std::vector<Point<2>>> rows;
    const auto                         add_row = [&](const auto &point) {
      rows.emplace_back();
      for (unsigned int j = 0; j < n_around; ++j)
        rows.back().push_back(point(j));
    };
    const double inner = inner_circle_radius(), outer = outer_circle_radius();
    for (unsigned int i = 0; i < n_inner_blend; ++i)
      {
        const double t = static_cast<double>(i) / n_inner_blend;
        add_row([&](const unsigned int j) {
          return Point<2>((1. - t) * on_square(core_half_width, j) +
                          t * on_circle(inner, j));
        });
      }
    for (const double r : circle_radii)
      add_row([&](const unsigned int j) { return on_circle(r, j); });
    for (unsigned int i = 1; i <= n_outer_blend; ++i)
      {
        const double t = static_cast<double>(i) / n_outer_blend;
        add_row([&](const unsigned int j) {
          return Point<2>((1. - t) * on_circle(outer, j) +
                          t * on_patch_boundary(j));
        });
      }

    // ring cells: local x radial (outwards), local y counter-clockwise
    for (unsigned int k = 0; k < rows.size(); ++k)
      {
        const unsigned int first = vertices.size();
        vertices.insert(vertices.end(), rows[k].begin(), rows[k].end());
        if (k + 1 == rows.size())
          break;
        for (unsigned int j = 0; j < n_around; ++j)
          {
            const unsigned int next = (j + 1) % n_around;
            CellData<2>        cell;
            cell.vertices = {first + j,
                             first + n_around + j,
                             first + next,
                             first + n_around + next};
            cells.push_back(cell);
          }
      }

    // the first row duplicates the core's boundary vertices
    SubCellData               no_subcells;
    std::vector<unsigned int> considered;
    GridTools::delete_duplicated_vertices(
      vertices, cells, no_subcells, considered, 1e-9 * core_half_width);
    GridTools::consistently_order_cells(cells);
    tria.create_triangulation(vertices, cells, no_subcells);
  }
} // namespace ssc
