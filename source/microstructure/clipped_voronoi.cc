// The only translation unit that includes CGAL (heavy templates).

#include <deal.II/base/exceptions.h>

#include <CGAL/Cartesian_converter.h>
#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_cell_base_with_info_3.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <utility>

#include <ssc/microstructure/clipped_voronoi.h>

namespace ssc
{
  namespace
  {
    using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
    using VertexBase =
      CGAL::Triangulation_vertex_base_with_info_3<unsigned int, Kernel>;
    // cells carry the index of their circumcentre in a flat array (CGAL's
    // cell base with circumcentre allocates each one on the heap)
    using CellBase = CGAL::Triangulation_cell_base_with_info_3<
      unsigned int,
      Kernel,
      CGAL::Delaunay_triangulation_cell_base_3<Kernel>>;
    using DataStructure =
      CGAL::Triangulation_data_structure_3<VertexBase, CellBase>;
    using Delaunay    = CGAL::Delaunay_triangulation_3<Kernel, DataStructure>;
    using CgalPoint   = Kernel::Point_3;
    using ExactKernel = CGAL::Exact_predicates_exact_constructions_kernel;

    Point<3>
    to_point(const CgalPoint &p)
    {
      return Point<3>(p.x(), p.y(), p.z());
    }

    /**
     * Coordinates in which mirroring is exact: x = origin + scale * u with
     * every u a multiple of 2^-40 in [0, 4). The image of u across the side
     * u_d = 0 is -u_d, across u_d = h_d it is 2 h_d - u_d, both exactly
     * representable, so a seed and its image are exactly symmetric and the
     * resulting cospherical configurations are resolved by CGAL's exact
     * predicates (no flat tetrahedra with ill-conditioned circumcentres).
     * Rounding to the grid moves points by at most 1e-12 of the box size.
     */
    class DyadicFrame
    {
    public:
      explicit DyadicFrame(const BoundingBox<3> &box)
        : origin(box.get_boundary_points().first)
      {
        const Point<3> &hi = box.get_boundary_points().second;
        scale =
          std::max({hi[0] - origin[0], hi[1] - origin[1], hi[2] - origin[2]});
        for (unsigned int d = 0; d < 3; ++d)
          extent[d] = snap((hi[d] - origin[d]) / scale);
      }

      Point<3>
      to_frame(const Point<3> &p) const
      {
        Point<3> u;
        for (unsigned int d = 0; d < 3; ++d)
          u[d] = snap((p[d] - origin[d]) / scale);
        return u;
      }

      Point<3>
      from_frame(const Point<3> &u) const
      {
        return origin + scale * u;
      }

      /// Image of @p u across side @p side (0: x min, 1: x max, ...).
      Point<3>
      mirror(const Point<3> &u, const unsigned int side) const
      {
        const unsigned int d     = side / 2;
        Point<3>           image = u;
        image[d] = side % 2 == 0 ? -u[d] : 2. * extent[d] - u[d];
        return image;
      }

      static double
      snap(const double x)
      {
        return std::ldexp(std::round(std::ldexp(x, 40)), -40);
      }

      Point<3> origin;
      double   scale;
      Point<3> extent;
    };


    /// Volume, first and second moment of the polygon's fan of tetrahedra
    /// with apex @p apex, added to @p cell.
    void
    add_pyramid(const Point<3>              &apex,
                const std::vector<Point<3>> &polygon,
                VoronoiCell                 &cell)
    {
      const Tensor<1, 3> a = polygon[0] - apex;
      for (unsigned int i = 1; i + 1 < polygon.size(); ++i)
        {
          const Tensor<1, 3> b = polygon[i] - apex;
          const Tensor<1, 3> c = polygon[i + 1] - apex;
          const double       v = std::abs(a * cross_product_3d(b, c)) / 6.;
          cell.volume += v;
          // centroid of the tetrahedron, relative to the apex: (a+b+c)/4
          cell.centroid += v * (apex + (a + b + c) / 4.);
          cell.second_moment +=
            v / 10. * (a * a + b * b + c * c + a * b + a * c + b * c);
        }
    }

    /// Area of a planar polygon given in cyclic order.
    double
    polygon_area(const std::vector<Point<3>> &polygon)
    {
      Tensor<1, 3> twice_area;
      for (unsigned int i = 1; i + 1 < polygon.size(); ++i)
        twice_area += cross_product_3d(polygon[i] - polygon[0],
                                       polygon[i + 1] - polygon[0]);
      return 0.5 * twice_area.norm();
    }


    // in frame units (the largest side of the box is 1)
    const double length_tolerance = 1e-12;
    const double area_tolerance   = 1e-14;


    /// The seeds in frame coordinates, moved at least 1e-6 inside the box
    /// (counted in @p diagnostics); throws for a seed outside it.
    std::vector<Point<3>>
    inset_seeds(const DyadicFrame           &frame,
                const std::vector<Point<3>> &seeds_in,
                VoronoiDiagnostics          &diagnostics)
    {
      const unsigned int n = seeds_in.size();
      // Seeds at least 1e-6 inside: a seed on a side would coincide with its
      // image, and a seed much closer to a side than that would make the
      // circumcentres of the cells around it ill-conditioned (their error
      // grows like the rounding error over the seed's distance to its image).
      std::vector<Point<3>> seeds(n);
      const double          inset = 1e-6;
      for (unsigned int i = 0; i < n; ++i)
        {
          const Point<3> u     = frame.to_frame(seeds_in[i]);
          bool           moved = false;
          for (unsigned int d = 0; d < 3; ++d)
            {
              AssertThrow(u[d] >= -1e-9 && u[d] <= frame.extent[d] + 1e-9,
                          ExcMessage("A Voronoi seed lies outside its box."));
              seeds[i][d] = DyadicFrame::snap(
                std::clamp(u[d], inset, frame.extent[d] - inset));
              moved = moved || seeds[i][d] != u[d];
            }
          diagnostics.n_seeds_moved_inside += moved;
        }
      return seeds;
    }


    /// The points to triangulate: the seeds and their mirror images across
    /// the sides within @p reach of them (every side if @p mirror_all).
    std::vector<std::pair<CgalPoint, unsigned int>>
    mirrored_points(const DyadicFrame           &frame,
                    const std::vector<Point<3>> &seeds,
                    const double                 reach,
                    const bool                   mirror_all)
    {
      const unsigned int n = seeds.size();
      // Seeds (info 0..n-1) and mirror images (info n + side n + i).
      std::vector<std::pair<CgalPoint, unsigned int>> points;
      points.reserve(n);
      for (unsigned int i = 0; i < n; ++i)
        points.emplace_back(CgalPoint(seeds[i][0], seeds[i][1], seeds[i][2]),
                            i);
      for (unsigned int side = 0; side < 6; ++side)
        for (unsigned int i = 0; i < n; ++i)
          {
            const unsigned int d = side / 2;
            const double       distance =
              side % 2 == 0 ? seeds[i][d] : frame.extent[d] - seeds[i][d];
            if (!mirror_all && distance > reach)
              continue;
            const Point<3> m = frame.mirror(seeds[i], side);
            points.emplace_back(CgalPoint(m[0], m[1], m[2]), n + side * n + i);
          }
      return points;
    }


    /// The vertex of each seed in @p delaunay; throws for a seed that
    /// coincides with another one (and so has none).
    std::vector<Delaunay::Vertex_handle>
    seed_vertices(const Delaunay              &delaunay,
                  const std::vector<Point<3>> &seeds_in)
    {
      const unsigned int                   n = seeds_in.size();
      std::vector<Delaunay::Vertex_handle> seed_vertex(n);
      for (auto v = delaunay.finite_vertices_begin();
           v != delaunay.finite_vertices_end();
           ++v)
        if (v->info() < n)
          seed_vertex[v->info()] = v;
      for (unsigned int i = 0; i < n; ++i)
        if (seed_vertex[i] == Delaunay::Vertex_handle())
          {
            std::ostringstream message;
            message << "Voronoi seed " << i << " at (" << seeds_in[i]
                    << ") coincides with another seed.";
            AssertThrow(false, ExcMessage(message.str()));
          }
      return seed_vertex;
    }


    /// Numbers the finite cells of @p delaunay (their info; infinite ones
    /// get an invalid index) and returns their circumcentres in that order.
    std::vector<Point<3>>
    cell_circumcentres(const Delaunay              &delaunay,
                       const DyadicFrame           &frame,
                       const std::vector<Point<3>> &seeds)
    {
      const unsigned int n = seeds.size();
      // Circumcentres in double precision, except for the cells at a seed
      // closer than 1e-3 to a side: there a seed and its image span a
      // sliver whose circumcentre's error grows like 1/distance^2, so it
      // is constructed exactly (CGAL's lazy exact kernel).
      const auto near_side = [&](const unsigned int info) {
        const unsigned int i = info < n ? info : (info - n) % n;
        for (unsigned int d = 0; d < 3; ++d)
          if (seeds[i][d] < 1e-3 || frame.extent[d] - seeds[i][d] < 1e-3)
            return true;
        return false;
      };
      const CGAL::Cartesian_converter<Kernel, ExactKernel> to_exact;
      std::vector<Point<3>>                                circumcentres;
      circumcentres.reserve(delaunay.number_of_finite_cells());
      for (auto c = delaunay.all_cells_begin(); c != delaunay.all_cells_end();
           ++c)
        if (delaunay.is_infinite(c))
          c->info() = numbers::invalid_unsigned_int;
        else
          {
            c->info()  = circumcentres.size();
            bool exact = false;
            for (unsigned int v = 0; v < 4; ++v)
              exact = exact || near_side(c->vertex(v)->info());
            if (exact)
              {
                const auto q =
                  CGAL::circumcenter(to_exact(c->vertex(0)->point()),
                                     to_exact(c->vertex(1)->point()),
                                     to_exact(c->vertex(2)->point()),
                                     to_exact(c->vertex(3)->point()));
                circumcentres.emplace_back(CGAL::to_double(q.x()),
                                           CGAL::to_double(q.y()),
                                           CGAL::to_double(q.z()));
              }
            else
              circumcentres.push_back(
                to_point(CGAL::circumcenter(c->vertex(0)->point(),
                                            c->vertex(1)->point(),
                                            c->vertex(2)->point(),
                                            c->vertex(3)->point())));
          }
      return circumcentres;
    }


    /// Fills @p polygon with the circumcentres of the cells around @p edge
    /// (the Voronoi face dual to it), merging a vertex that coincides with
    /// its predecessor; false if one is infinite or outside the box.
    bool
    dual_polygon(const Delaunay              &delaunay,
                 const Delaunay::Edge        &edge,
                 const std::vector<Point<3>> &circumcentres,
                 const DyadicFrame           &frame,
                 std::vector<Point<3>>       &polygon,
                 VoronoiDiagnostics          &found)
    {
      bool complete = true;
      polygon.clear();
      auto       circulator = delaunay.incident_cells(edge);
      const auto first      = circulator;
      do
        {
          if (circulator->info() == numbers::invalid_unsigned_int)
            {
              complete = false;
              break;
            }
          const Point<3> &q = circumcentres[circulator->info()];
          for (unsigned int d = 0; d < 3; ++d)
            complete =
              complete && q[d] > -1e-9 && q[d] < frame.extent[d] + 1e-9;
          if (!polygon.empty() &&
              q.distance(polygon.back()) <= length_tolerance)
            ++found.n_merged_vertices;
          else
            polygon.push_back(q);
        }
      while (++circulator != first);
      return complete;
    }


    /// Adds the face @p polygon of area @p area between seed @p i and
    /// point @p other (a seed or a mirror image) to the cells of its seeds.
    void
    add_face(const unsigned int           i,
             const unsigned int           other,
             const std::vector<Point<3>> &polygon,
             const double                 area,
             const std::vector<Point<3>> &seeds,
             const bool                   with_faces,
             std::vector<VoronoiCell>    &cells)
    {
      const unsigned int                n    = seeds.size();
      const std::array<unsigned int, 2> ends = {{i, other}};
      for (unsigned int end = 0; end < 2; ++end)
        {
          const unsigned int a = ends[end], b = ends[1 - end];
          if (a >= n)
            continue;
          add_pyramid(seeds[a], polygon, cells[a]);
          if (with_faces)
            cells[a].faces.push_back(
              {b < n ? static_cast<int>(b) : -1 - static_cast<int>((b - n) / n),
               polygon,
               area});
        }
    }


    /// Computes the cells of the seeds (in frame units) into @p cells, the
    /// faces dropped and vertices merged into @p found; false (and stops)
    /// if a cell is not closed inside the box by the mirror images.
    bool
    build_cells(const Delaunay                             &delaunay,
                const std::vector<Delaunay::Vertex_handle> &seed_vertex,
                const std::vector<Point<3>>                &circumcentres,
                const std::vector<Point<3>>                &seeds,
                const DyadicFrame                          &frame,
                const bool                                  with_faces,
                std::vector<VoronoiCell>                   &cells,
                VoronoiDiagnostics                         &found)
    {
      const unsigned int                   n = seeds.size();
      std::vector<Point<3>>                polygon;
      std::vector<Delaunay::Cell_handle>   incident;
      std::vector<Delaunay::Vertex_handle> neighbours;
      bool                                 complete = true;
      // Every Delaunay edge (v, w) at a seed v is dual to a face of v's
      // cell: the polygon of the circumcentres of the cells around it. A
      // face between two seeds is computed once, from the lower index.
      for (unsigned int i = 0; complete && i < n; ++i)
        {
          const Delaunay::Vertex_handle v = seed_vertex[i];
          incident.clear();
          delaunay.incident_cells(v, std::back_inserter(incident));
          neighbours.clear();
          for (const auto &c : incident)
            for (unsigned int k = 0; k < 4; ++k)
              {
                const Delaunay::Vertex_handle w = c->vertex(k);
                if (w == v || delaunay.is_infinite(w) ||
                    (w->info() < n && w->info() < i) ||
                    std::find(neighbours.begin(), neighbours.end(), w) !=
                      neighbours.end())
                  continue;
                neighbours.push_back(w);
                const unsigned int other = w->info();
                // a seed and another seed's image meet only in a side
                // of the box, in a face of zero area
                if (other >= n && (other - n) % n != i)
                  {
                    ++found.n_degenerate_faces;
                    continue;
                  }

                const Delaunay::Edge edge(c, c->index(v), k);
                if (!dual_polygon(
                      delaunay, edge, circumcentres, frame, polygon, found))
                  complete = false;
                if (!complete)
                  break;
                while (polygon.size() > 1 &&
                       polygon.front().distance(polygon.back()) <=
                         length_tolerance)
                  {
                    polygon.pop_back();
                    ++found.n_merged_vertices;
                  }
                const double area =
                  polygon.size() >= 3 ? polygon_area(polygon) : 0.;
                if (area <= area_tolerance)
                  {
                    ++found.n_degenerate_faces;
                    continue;
                  }

                add_face(i, other, polygon, area, seeds, with_faces, cells);
              }
        }
      return complete;
    }


    /// Takes @p cells from the frame back to the box's coordinates (and the
    /// centroids from first moments to points); throws for an empty cell.
    void
    cells_to_box(const DyadicFrame &frame, std::vector<VoronoiCell> &cells)
    {
      const double h = frame.scale;
      for (auto &cell : cells)
        {
          AssertThrow(cell.volume > 0,
                      ExcMessage("Internal error: empty Voronoi cell."));
          cell.centroid = frame.from_frame(cell.centroid / cell.volume);
          cell.second_moment *= h * h * h * h * h;
          cell.volume *= h * h * h;
          for (auto &face : cell.faces)
            {
              face.area *= h * h;
              for (auto &vertex : face.vertices)
                vertex = frame.from_frame(vertex);
            }
        }
    }
  } // namespace


  std::vector<VoronoiCell>
  compute_clipped_voronoi(const BoundingBox<3>        &box,
                          const std::vector<Point<3>> &seeds_in,
                          const bool                   with_faces,
                          VoronoiDiagnostics          &diagnostics)
  {
    const unsigned int n = seeds_in.size();
    AssertThrow(n > 0, ExcMessage("A Voronoi tessellation needs a seed."));
    const Point<3> &lo = box.get_boundary_points().first;
    const Point<3> &hi = box.get_boundary_points().second;
    for (unsigned int d = 0; d < 3; ++d)
      AssertThrow(hi[d] > lo[d],
                  ExcMessage("The box of a Voronoi tessellation must have a "
                             "positive extent in every direction."));
    const DyadicFrame frame(box);

    const std::vector<Point<3>> seeds =
      inset_seeds(frame, seeds_in, diagnostics);

    // Mirror images matter only for seeds whose cell reaches a side. Start
    // with the seeds within two mean spacings of a side and widen the reach
    // until every cell closes inside the box: a cell of the partially
    // mirrored set that lies in the box is exact, since no missing image is
    // closer to a point of the box than its original.
    const double volume = frame.extent[0] * frame.extent[1] * frame.extent[2];
    const double largest_extent =
      std::max({frame.extent[0], frame.extent[1], frame.extent[2]});
    double reach = 2. * std::cbrt(volume / n);
    for (;;)
      {
        const bool mirror_all = reach >= largest_extent;
        const std::vector<std::pair<CgalPoint, unsigned int>> points =
          mirrored_points(frame, seeds, reach, mirror_all);
        const Delaunay delaunay(points.begin(), points.end());
        // Few seeds in a thin or needle-shaped box: the seeds and the
        // images within reach may be coplanar or collinear, and the
        // triangulation then has no cells to dualise. Mirroring across
        // every side spans all three directions.
        if (delaunay.dimension() < 3)
          {
            AssertThrow(!mirror_all,
                        ExcMessage("Internal error: the mirrored Voronoi "
                                   "seeds span fewer than three dimensions."));
            reach = 2. * largest_extent;
            continue;
          }

        const std::vector<Delaunay::Vertex_handle> seed_vertex =
          seed_vertices(delaunay, seeds_in);
        const std::vector<Point<3>> circumcentres =
          cell_circumcentres(delaunay, frame, seeds);

        std::vector<VoronoiCell> cells(n);
        VoronoiDiagnostics       found;
        if (!build_cells(delaunay,
                         seed_vertex,
                         circumcentres,
                         seeds,
                         frame,
                         with_faces,
                         cells,
                         found))
          {
            AssertThrow(!mirror_all,
                        ExcMessage("Internal error: a Voronoi cell is not "
                                   "closed by the mirror images of its "
                                   "seed."));
            reach *= 2.;
            continue;
          }

        diagnostics.n_degenerate_faces += found.n_degenerate_faces;
        diagnostics.n_merged_vertices += found.n_merged_vertices;
        // back from the frame to the box's coordinates
        cells_to_box(frame, cells);
        return cells;
      }
  }


  std::vector<double>
  lloyd_relaxation(const BoundingBox<3>                    &box,
                   std::vector<Point<3>>                   &seeds,
                   const unsigned int                       n_iterations,
                   const std::function<void(unsigned int)> &after_iteration)
  {
    std::vector<double> energies;
    for (unsigned int iteration = 0;; ++iteration)
      {
        VoronoiDiagnostics             diagnostics;
        const std::vector<VoronoiCell> cells =
          compute_clipped_voronoi(box, seeds, false, diagnostics);
        double energy = 0;
        for (const auto &cell : cells)
          energy += cell.second_moment;
        energies.push_back(energy);
        if (iteration == n_iterations)
          break;
        for (unsigned int i = 0; i < seeds.size(); ++i)
          seeds[i] = cells[i].centroid;
        if (after_iteration)
          after_iteration(iteration + 1);
      }
    return energies;
  }
} // namespace ssc
