#ifndef ssc_embedding_point_locator_h
#define ssc_embedding_point_locator_h

#include <deal.II/base/bounding_box.h>
#include <deal.II/base/point.h>

#include <deal.II/distributed/tria.h>

#include <deal.II/fe/mapping.h>

#include <deal.II/numerics/rtree.h>

#include <utility>
#include <vector>

namespace ssc
{
  using namespace dealii;

  /// Where one point lies in the background mesh, as seen by this rank.
  struct PointLocation
  {
    /// The locally owned cell that holds the point, or an invalid iterator
    /// if another rank owns it.
    Triangulation<3>::active_cell_iterator cell;
    /// The point in the reference coordinates of that cell.
    Point<3> unit_point;
  };

  /**
   * Finds, for points given identically on every rank (the embedded
   * microstructure is built whole on each rank), the background cell that
   * holds each point, on a parallel::distributed mesh: an R-tree of the
   * bounding boxes of the locally owned and ghost cells proposes candidates,
   * the mapping confirms them in reference coordinates, and a point on a
   * face, edge or vertex shared by several cells goes to the cell with the
   * smallest CellId; a point in one of the thin gaps that hanging nodes on
   * a curved interface leave between trilinear cells goes to the nearest
   * cell. Every rank sees all cells around a point that lies in
   * one of its own cells (the ghost layer holds all vertex neighbours), so
   * all ranks agree and each point is taken by exactly one rank. A point
   * that no rank can place is an error, never dropped.
   */
  class PointLocator
  {
  public:
    PointLocator(const parallel::distributed::Triangulation<3> &tria,
                 const Mapping<3>                              &mapping);

    /// Locates @p points (the same on every rank; collective). Throws,
    /// naming the first such point, if a point lies in no cell.
    std::vector<PointLocation>
    locate(const std::vector<Point<3>> &points) const;

    /// The locally owned cells whose bounding boxes meet @p box.
    std::vector<Triangulation<3>::active_cell_iterator>
    owned_cells_meeting(const BoundingBox<3> &box) const;

    const Mapping<3> &
    get_mapping() const
    {
      return mapping;
    }

    MPI_Comm
    communicator() const
    {
      return tria.get_communicator();
    }

    /// Tolerance on the reference coordinates for a point to count as
    /// inside a cell.
    static constexpr double unit_tolerance = 1e-8;

    /// A point inside no cell goes to the nearest one (in reference
    /// coordinates) if it is at most this far outside it, and is projected
    /// onto it: hanging nodes on a curved layer interface leave such thin
    /// gaps between trilinear cells.
    static constexpr double gap_tolerance = 1e-2;

  private:
    using Leaf =
      std::pair<BoundingBox<3>, Triangulation<3>::active_cell_iterator>;

    const parallel::distributed::Triangulation<3> &tria;
    const Mapping<3>                              &mapping;
    RTree<Leaf>                                    tree;
  };
} // namespace ssc

#endif
