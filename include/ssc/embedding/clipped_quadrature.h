#ifndef ssc_embedding_clipped_quadrature_h
#define ssc_embedding_clipped_quadrature_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <deal.II/grid/tria.h>

#include <vector>

#include <ssc/embedding/point_locator.h>

namespace ssc
{
  /// The quadrature of an embedded mesh inside one background cell.
  struct CellQuadrature
  {
    Triangulation<3>::active_cell_iterator cell;
    std::vector<Point<3>>                  unit_points;
    std::vector<double>                    JxW;
    /// Unit normal (membrane) or tangent (cable) at each point.
    std::vector<Tensor<1, 3>>       directions;
    std::vector<types::material_id> materials;
  };

  /**
   * Quadrature of an embedded mesh (triangles of a Triangulation<2,3> or
   * segments of a Triangulation<1,3>) split exactly along the background
   * cells: every embedded cell is clipped against each locally owned
   * background cell it meets, and every piece gets a Gauss rule of
   * @p n_points_per_direction points per direction (triangles: 1, 3, 6, 7
   * points; segments: Gauss). Inside one background cell the background
   * shape functions are smooth, so this integrates the embedded energy
   * exactly for affine background cells, whatever the sizes of the two
   * meshes, and each piece belongs to exactly one rank.
   *
   * The background cells are clipped as convex polyhedra bounded by the
   * planes of their faces (exact for the layered mesh's vertical side faces
   * and for horizontal layer interfaces; the best-fit plane of a warped
   * face otherwise).
   *
   * @p covered returns the total measure (area or length) of the pieces on
   * all ranks: it equals the measure of the embedded mesh inside the
   * background mesh up to the thin gaps and overlaps of warped faces.
   */
  template <int dim>
  std::vector<CellQuadrature>
  clipped_quadrature(const Triangulation<dim, 3> &embedded,
                     const PointLocator          &locator,
                     const unsigned int           n_points_per_direction,
                     double                      &covered);
} // namespace ssc

#endif
