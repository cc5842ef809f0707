#ifndef ssc_mesh_o_grid_h
#define ssc_mesh_o_grid_h

#include <deal.II/base/point.h>

#include <deal.II/grid/tria.h>

#include <vector>

#include <ssc/mesh/mesh_parameters.h>

namespace ssc
{
  /**
   * The lateral mesh of Mesh/Layout = o-grid: rings of quadrilaterals
   * around the circle r = a (the punch edge), the classic mesh of a
   * circular contact. At a flat punch's edge the field is singular in the
   * (r, z) plane and smooth around the circle, so the cells there are thin
   * radially (Edge cell size, growing by Radial grading away from the
   * circle, inwards and outwards, until they are about square) and only
   * Cells around in the angular direction: equal accuracy with far fewer
   * cells than isotropic refinement towards the edge.
   *
   * From the centre out: a square core of (n/4)^2 cells (n = Cells around),
   * blend rings from the core's square to the first circle, circular rings
   * from the radius inner_circle_radius() to outer_circle_radius() (the
   * circle r = a among them), and, for a square patch, blend rings from the
   * last circle to the patch boundary. Angles are uniform, starting at the
   * corner direction -45 degrees, so the core's and the patch's corners are
   * vertices. Vertices between the two circle radii lie on circles, which
   * the polar LayerManifold keeps under refinement.
   */
  class OGrid
  {
  public:
    explicit OGrid(const MeshParameters &parameters);

    /// Number of quadrilaterals.
    unsigned int
    n_cells() const;

    /// Fills @p tria (empty) with the lateral mesh in physical (x, y)
    /// coordinates; boundary ids are left at 0.
    void
    make(Triangulation<2> &tria) const;

    /// Radii (mm) between which every vertex lies on a circle.
    double
    inner_circle_radius() const
    {
      return circle_radii.front();
    }

    double
    outer_circle_radius() const
    {
      return circle_radii.back();
    }

  private:
    /// Vertex j of the square of half width @p half_width around the
    /// centre, or of the patch boundary, or of the circle of radius r.
    Point<2>
    on_square(const double half_width, const unsigned int j) const;

    Point<2>
    on_patch_boundary(const unsigned int j) const;

    Point<2>
    on_circle(const double r, const unsigned int j) const;

    double
    angle(const unsigned int j) const;

    const MeshParameters &parameters;
    const unsigned int    n_around;
    /// Radii of the circular rings, increasing; the circle a among them.
    std::vector<double> circle_radii;
    double              core_half_width;
    unsigned int        n_inner_blend;
    unsigned int        n_outer_blend;
  };
} // namespace ssc

#endif
