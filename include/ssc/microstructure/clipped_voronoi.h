#ifndef ssc_microstructure_clipped_voronoi_h
#define ssc_microstructure_clipped_voronoi_h

#include <deal.II/base/bounding_box.h>
#include <deal.II/base/point.h>

#include <functional>
#include <vector>

namespace ssc
{
  using namespace dealii;

  /// One planar face of a clipped Voronoi cell.
  struct VoronoiFace
  {
    /// Index of the seed on the other side (>= 0), or -1 - k for side k of
    /// the box (0: x min, 1: x max, 2: y min, 3: y max, 4: z min, 5: z max).
    int neighbour;
    /// The vertices in cyclic order.
    std::vector<Point<3>> vertices;
    double                area;
  };

  /// One cell of the tessellation: the points of the box closer to its seed
  /// than to any other seed.
  struct VoronoiCell
  {
    double   volume = 0;
    Point<3> centroid;
    /// The cell's term of the CVT energy, the integral of |x - seed|^2.
    double second_moment = 0;
    /// Faces of positive area (empty unless asked for).
    std::vector<VoronoiFace> faces;
  };

  /// What the tessellation had to clean up.
  struct VoronoiDiagnostics
  {
    /// Faces of (numerically) zero area, from cospherical seeds: dropped.
    unsigned int n_degenerate_faces = 0;
    /// Polygon vertices that coincided with their predecessor: merged.
    unsigned int n_merged_vertices = 0;
    /// Seeds on or outside the box that were moved just inside it.
    unsigned int n_seeds_moved_inside = 0;
  };

  /**
   * The Voronoi tessellation of seeds in an axis-parallel box, every cell
   * clipped exactly to the box. Built with CGAL's 3D Delaunay triangulation
   * of the seeds and their mirror images across the six sides of the box:
   * inside the box no mirror image is closer than its original, outside it
   * the mirror across the nearest side is closer than the seed itself, so
   * the Voronoi cell of a seed in the augmented set is its cell clipped to
   * the box, and the sides of the box appear as the faces between a seed and
   * its own mirror image. Exact predicates keep degenerate (coplanar,
   * cospherical, lattice) seeds valid; faces of numerically zero area that
   * such seeds produce are dropped and counted.
   *
   * Seeds on or within 1e-6 (of the box's largest side) of the boundary are
   * moved that far inside (a seed's mirror image must not coincide with it
   * or come so close that circumcentres become ill-conditioned). Two
   * coinciding seeds are an error.
   */
  std::vector<VoronoiCell>
  compute_clipped_voronoi(const BoundingBox<3>        &box,
                          const std::vector<Point<3>> &seeds,
                          const bool                   with_faces,
                          VoronoiDiagnostics          &diagnostics);

  /**
   * Lloyd's algorithm: @p n_iterations times, move every seed to the
   * centroid of its clipped Voronoi cell, which converges towards a
   * centroidal Voronoi tessellation (CVT). Returns the CVT energy
   * sum_i int_{V_i} |x - p_i|^2 dx of the initial seeds and after every
   * iteration (n_iterations + 1 values, non-increasing in exact arithmetic).
   * @p after_iteration (if given) is called with the number of iterations
   * done after each one (progress reports).
   */
  std::vector<double>
  lloyd_relaxation(
    const BoundingBox<3>                    &box,
    std::vector<Point<3>>                   &seeds,
    const unsigned int                       n_iterations,
    const std::function<void(unsigned int)> &after_iteration = {});
} // namespace ssc

#endif
