#include <deal.II/base/exceptions.h>
#include <deal.II/base/geometry_info.h>
#include <deal.II/base/mpi.templates.h>

#include <deal.II/fe/mapping.h>

#include <boost/geometry/index/rtree.hpp>

#include <limits>
#include <sstream>

#include <ssc/embedding/point_locator.h>

namespace ssc
{
  PointLocator::PointLocator(
    const parallel::distributed::Triangulation<3> &tria,
    const Mapping<3>                              &mapping)
    : tria(tria)
    , mapping(mapping)
  {
    std::vector<Leaf> leaves;
    for (const auto &cell : tria.active_cell_iterators())
      if (cell->is_locally_owned() || cell->is_ghost())
        {
          BoundingBox<3> box = mapping.get_bounding_box(cell);
          box.extend(gap_tolerance * cell->diameter());
          leaves.emplace_back(box, cell);
        }
    tree = pack_rtree(leaves);
  }


  std::vector<Triangulation<3>::active_cell_iterator>
  PointLocator::owned_cells_meeting(const BoundingBox<3> &box) const
  {
    namespace bgi = boost::geometry::index;
    std::vector<Leaf> candidates;
    tree.query(bgi::intersects(box), std::back_inserter(candidates));
    std::vector<Triangulation<3>::active_cell_iterator> cells;
    for (const auto &candidate : candidates)
      if (candidate.second->is_locally_owned())
        cells.push_back(candidate.second);
    return cells;
  }


  std::vector<PointLocation>
  PointLocator::locate(const std::vector<Point<3>> &points) const
  {
    namespace bgi = boost::geometry::index;
    std::vector<PointLocation> locations(points.size());
    // per point: 1 if this rank saw a cell holding it (owned or ghost)
    std::vector<unsigned int> seen(points.size(), 0);
    std::vector<Leaf>         candidates;
    for (unsigned int k = 0; k < points.size(); ++k)
      {
        candidates.clear();
        tree.query(bgi::intersects(points[k]), std::back_inserter(candidates));
        // The cell that holds the point (smallest CellId on ties), or else
        // the nearest one in reference coordinates: trilinear cells leave
        // small gaps where hanging nodes sit on a curved layer manifold.
        Triangulation<3>::active_cell_iterator best;
        Point<3>                               best_unit;
        double best_distance = std::numeric_limits<double>::max();
        for (const auto &candidate : candidates)
          {
            Point<3> unit;
            try
              {
                unit = mapping.transform_real_to_unit_cell(candidate.second,
                                                           points[k]);
              }
            catch (const typename Mapping<3>::ExcTransformationFailed &)
              {
                continue;
              }
            const double distance =
              std::max(GeometryInfo<3>::distance_to_unit_cell(unit) -
                         unit_tolerance,
                       0.);
            if (distance < best_distance ||
                (distance == best_distance &&
                 candidate.second->id() < best->id()))
              {
                best          = candidate.second;
                best_unit     = unit;
                best_distance = distance;
              }
          }
        if (best.state() == IteratorState::valid &&
            best_distance <= gap_tolerance)
          {
            seen[k] = 1;
            if (best->is_locally_owned())
              {
                locations[k].cell = best;
                locations[k].unit_point =
                  GeometryInfo<3>::project_to_unit_cell(best_unit);
              }
          }
      }

    // Every point must have been seen by some rank.
    const MPI_Comm communicator = tria.get_communicator();
    Utilities::MPI::max(seen, communicator, seen);
    for (unsigned int k = 0; k < points.size(); ++k)
      if (seen[k] == 0)
        {
          std::ostringstream message;
          message << "The point (" << points[k]
                  << ") lies in no cell of the background mesh (outside "
                     "the layered patch?).";
          AssertThrow(false, ExcMessage(message.str()));
        }
    unsigned int taken = 0;
    for (const auto &location : locations)
      taken += location.cell.state() == IteratorState::valid;
    AssertThrow(Utilities::MPI::sum(taken, communicator) == points.size(),
                ExcMessage("Internal error: an embedded point was taken by "
                           "more than one rank or by none."));
    return locations;
  }
} // namespace ssc
