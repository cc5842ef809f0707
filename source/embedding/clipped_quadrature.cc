#include <deal.II/base/exceptions.h>
#include <deal.II/base/geometry_info.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>

#include <array>
#include <cmath>
#include <map>

#include <ssc/embedding/clipped_quadrature.h>

namespace ssc
{
  namespace
  {
    /// The half-space normal . x <= offset. Of the two cells that share a
    /// face, only the one whose outward normal points in the positive
    /// lexicographic direction keeps what lies in the face itself, so that
    /// a membrane on a face or a cable along an edge is counted once.
    struct Plane
    {
      Tensor<1, 3> normal;
      double       offset;
      double       tolerance;

      bool
      owns_its_face() const
      {
        for (unsigned int d = 0; d < 3; ++d)
          if (std::abs(normal[d]) > 1e-12)
            return normal[d] > 0;
        return true;
      }
    };

    /// The six face planes of a hexahedron, normals outwards.
    std::array<Plane, 6>
    face_planes(const Triangulation<3>::active_cell_iterator &cell)
    {
      Point<3> centre;
      for (const unsigned int v : cell->vertex_indices())
        centre += cell->vertex(v) / 8.;
      std::array<Plane, 6> planes;
      for (const unsigned int f : cell->face_indices())
        {
          const auto face = cell->face(f);
          Point<3>   face_centre;
          for (unsigned int v = 0; v < 4; ++v)
            face_centre += face->vertex(v) / 4.;
          // the cross product of the diagonals: exact for a planar face, the
          // best-fit normal of a warped one
          Tensor<1, 3> n = cross_product_3d(face->vertex(3) - face->vertex(0),
                                            face->vertex(2) - face->vertex(1));
          if (n * (face_centre - centre) < 0)
            n = -n;
          n /= n.norm();
          planes[f] = {n, n * face_centre, 1e-10 * cell->diameter()};
        }
      return planes;
    }

    /// Sutherland-Hodgman: keeps the part of @p polygon inside @p plane.
    void
    clip(std::vector<Point<3>> &polygon,
         const Plane           &plane,
         std::vector<Point<3>> &scratch)
    {
      scratch.clear();
      const unsigned int n        = polygon.size();
      bool               in_plane = true;
      for (const Point<3> &p : polygon)
        in_plane = in_plane &&
                   std::abs(plane.normal * p - plane.offset) <= plane.tolerance;
      if (in_plane)
        {
          if (!plane.owns_its_face())
            polygon.clear();
          return;
        }
      for (unsigned int i = 0; i < n; ++i)
        {
          const Point<3> &a  = polygon[i];
          const Point<3> &b  = polygon[(i + 1) % n];
          const double    da = plane.normal * a - plane.offset;
          const double    db = plane.normal * b - plane.offset;
          if (da <= 0)
            scratch.push_back(a);
          if ((da < 0 && db > 0) || (da > 0 && db < 0))
            scratch.push_back(a + (da / (da - db)) * (b - a));
        }
      polygon.swap(scratch);
    }

    /// Adds the point @p x with weight @p JxW in @p cell to @p quadrature.
    void
    add_point(CellQuadrature          &quadrature,
              const Mapping<3>        &mapping,
              const Point<3>          &x,
              const double             JxW,
              const Tensor<1, 3>      &direction,
              const types::material_id material)
    {
      Point<3> unit;
      try
        {
          unit = mapping.transform_real_to_unit_cell(quadrature.cell, x);
        }
      catch (const typename Mapping<3>::ExcTransformationFailed &)
        {
          AssertThrow(false,
                      ExcMessage("Internal error: a clipped quadrature point "
                                 "could not be mapped into its cell."));
        }
      quadrature.unit_points.push_back(
        GeometryInfo<3>::project_to_unit_cell(unit));
      quadrature.JxW.push_back(JxW);
      quadrature.directions.push_back(direction);
      quadrature.materials.push_back(material);
    }

    /// The cells' quadratures that hold points.
    std::vector<CellQuadrature>
    non_empty(
      std::map<Triangulation<3>::active_cell_iterator, CellQuadrature> &cells)
    {
      std::vector<CellQuadrature> result;
      for (auto &entry : cells)
        if (!entry.second.JxW.empty())
          result.push_back(std::move(entry.second));
      return result;
    }
  } // namespace


  template <>
  std::vector<CellQuadrature>
  clipped_quadrature(const Triangulation<2, 3> &embedded,
                     const PointLocator        &locator,
                     const unsigned int         n_points_per_direction,
                     double                    &covered)
  {
    const QGaussSimplex<2> rule(n_points_per_direction);
    const Mapping<3>      &mapping = locator.get_mapping();
    std::map<Triangulation<3>::active_cell_iterator, CellQuadrature> by_cell;
    std::vector<Point<3>> polygon, scratch;
    double                local_area = 0;
    for (const auto &triangle : embedded.active_cell_iterators())
      {
        AssertThrow(triangle->n_vertices() == 3,
                    ExcMessage("Embedded membranes must be triangles."));
        Tensor<1, 3> normal =
          cross_product_3d(triangle->vertex(1) - triangle->vertex(0),
                           triangle->vertex(2) - triangle->vertex(0));
        const double area = 0.5 * normal.norm();
        if (area == 0.)
          continue;
        normal /= normal.norm();
        for (const auto &cell :
             locator.owned_cells_meeting(triangle->bounding_box()))
          {
            polygon = {triangle->vertex(0),
                       triangle->vertex(1),
                       triangle->vertex(2)};
            for (const Plane &plane : face_planes(cell))
              {
                clip(polygon, plane, scratch);
                if (polygon.size() < 3)
                  break;
              }
            if (polygon.size() < 3)
              continue;
            CellQuadrature &quadrature = by_cell[cell];
            quadrature.cell            = cell;
            for (unsigned int k = 1; k + 1 < polygon.size(); ++k)
              {
                const Tensor<1, 3> a           = polygon[k] - polygon[0];
                const Tensor<1, 3> b           = polygon[k + 1] - polygon[0];
                const double       twice_piece = cross_product_3d(a, b).norm();
                if (twice_piece <= 1e-14 * area)
                  continue;
                local_area += 0.5 * twice_piece;
                for (unsigned int q = 0; q < rule.size(); ++q)
                  add_point(quadrature,
                            mapping,
                            polygon[0] + rule.point(q)[0] * a +
                              rule.point(q)[1] * b,
                            rule.weight(q) * twice_piece,
                            normal,
                            triangle->material_id());
              }
          }
      }
    covered = Utilities::MPI::sum(local_area, locator.communicator());
    return non_empty(by_cell);
  }


  template <>
  std::vector<CellQuadrature>
  clipped_quadrature(const Triangulation<1, 3> &embedded,
                     const PointLocator        &locator,
                     const unsigned int         n_points_per_direction,
                     double                    &covered)
  {
    const QGauss<1>   rule(n_points_per_direction);
    const Mapping<3> &mapping = locator.get_mapping();
    std::map<Triangulation<3>::active_cell_iterator, CellQuadrature> by_cell;
    double local_length = 0;
    for (const auto &segment : embedded.active_cell_iterators())
      {
        const Point<3>     a      = segment->vertex(0);
        const Tensor<1, 3> edge   = segment->vertex(1) - a;
        const double       length = edge.norm();
        if (length == 0.)
          continue;
        for (const auto &cell :
             locator.owned_cells_meeting(segment->bounding_box()))
          {
            // the parameter interval [t0, t1] of the segment inside the cell
            double t0 = 0, t1 = 1;
            for (const Plane &plane : face_planes(cell))
              {
                const double da    = plane.normal * a - plane.offset;
                const double slope = plane.normal * edge;
                if (std::abs(da) <= plane.tolerance &&
                    std::abs(da + slope) <= plane.tolerance)
                  {
                    if (!plane.owns_its_face())
                      t1 = -1; // in the face, which the neighbour keeps
                  }
                else if (slope == 0.)
                  {
                    if (da > 0)
                      t1 = -1; // parallel and outside
                  }
                else if (slope > 0)
                  t1 = std::min(t1, -da / slope);
                else
                  t0 = std::max(t0, -da / slope);
              }
            if (t1 - t0 <= 1e-14)
              continue;
            CellQuadrature &quadrature = by_cell[cell];
            quadrature.cell            = cell;
            local_length += (t1 - t0) * length;
            for (unsigned int q = 0; q < rule.size(); ++q)
              add_point(quadrature,
                        mapping,
                        a + (t0 + rule.point(q)[0] * (t1 - t0)) * edge,
                        rule.weight(q) * (t1 - t0) * length,
                        edge / length,
                        segment->material_id());
          }
      }
    covered = Utilities::MPI::sum(local_length, locator.communicator());
    return non_empty(by_cell);
  }
} // namespace ssc
