// The clipped Voronoi tessellation of seeds in a box: cell volumes sum to
// the box volume (relative 1e-10); every face between two seeds appears in
// both cells with the same area; the box sides are covered exactly; and
// degenerate seeds -- a cubic lattice (cospherical), coplanar seeds, seeds
// on faces, edges and corners of the box, a single seed in a thin or
// needle-shaped box -- give valid tessellations.
// Coinciding seeds are reported as an error.

#include <cmath>
#include <iomanip>
#include <map>
#include <random>

#include <ssc/microstructure/clipped_voronoi.h>

#include "tests.h"

using namespace dealii;

void
check(const std::string           &label,
      const BoundingBox<3>        &box,
      const std::vector<Point<3>> &seeds)
{
  ssc::VoronoiDiagnostics diagnostics;
  const auto              cells =
    ssc::compute_clipped_voronoi(box, seeds, true, diagnostics);
  double                                volume = 0, side_area = 0;
  std::map<std::pair<int, int>, double> faces; // (i, j) -> area
  unsigned int                          empty = 0;
  for (unsigned int i = 0; i < cells.size(); ++i)
    {
      volume += cells[i].volume;
      empty += cells[i].volume <= 0;
      for (const auto &face : cells[i].faces)
        if (face.neighbour < 0)
          side_area += face.area;
        else
          faces[{int(i), face.neighbour}] += face.area;
    }
  unsigned int unmatched = 0, area_mismatch = 0, doubled = 0;
  for (const auto &[pair, area] : faces)
    {
      const auto mirror = faces.find({pair.second, pair.first});
      if (mirror == faces.end())
        ++unmatched;
      else if (std::abs(mirror->second - area) > 1e-12 * (1 + area))
        ++area_mismatch;
    }
  for (unsigned int i = 0; i < cells.size(); ++i)
    {
      std::map<int, unsigned int> count;
      for (const auto &face : cells[i].faces)
        doubled += ++count[face.neighbour] > 1;
    }
  const Point<3> &lo         = box.get_boundary_points().first;
  const Point<3> &hi         = box.get_boundary_points().second;
  const double    box_volume = box.volume();
  const double    box_area =
    2 * ((hi[0] - lo[0]) * (hi[1] - lo[1]) + (hi[1] - lo[1]) * (hi[2] - lo[2]) +
         (hi[0] - lo[0]) * (hi[2] - lo[2]));
  deallog << label << ": " << cells.size() << " cells, " << faces.size() / 2
          << " interior faces" << std::endl;
  deallog << "  volume sum / box volume - 1 below 1e-10: "
          << (std::abs(volume / box_volume - 1) < 1e-10 ? "yes" : "no")
          << "; side area / box area - 1 below 1e-10: "
          << (std::abs(side_area / box_area - 1) < 1e-10 ? "yes" : "no")
          << std::endl;
  deallog << "  empty cells " << empty << ", one-sided faces " << unmatched
          << ", faces with different areas " << area_mismatch
          << ", repeated neighbours " << doubled << std::endl;
}

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  const BoundingBox<3> box(
    std::make_pair(Point<3>(-3, 1, -2.5), Point<3>(5, 4, 0.5)));
  const Point<3> &lo = box.get_boundary_points().first;

  std::mt19937                           generator(3);
  std::uniform_real_distribution<double> uniform(0., 1.);
  std::vector<Point<3>>                  random(500);
  for (auto &p : random)
    for (unsigned int d = 0; d < 3; ++d)
      p[d] = lo[d] + uniform(generator) * box.side_length(d);
  check("random seeds", box, random);

  // cubic lattice: every cell of the Delaunay triangulation is cospherical
  std::vector<Point<3>> lattice;
  for (unsigned int i = 0; i < 8; ++i)
    for (unsigned int j = 0; j < 3; ++j)
      for (unsigned int k = 0; k < 3; ++k)
        lattice.emplace_back(lo[0] + 0.5 + i, lo[1] + 0.5 + j, lo[2] + 0.5 + k);
  check("cubic lattice", box, lattice);

  std::vector<Point<3>> coplanar;
  for (unsigned int i = 0; i < 40; ++i)
    coplanar.emplace_back(lo[0] + uniform(generator) * 8,
                          lo[1] + uniform(generator) * 3,
                          -1.);
  check("coplanar seeds", box, coplanar);

  std::vector<Point<3>> on_boundary = {Point<3>(-3, 1, -2.5), // corner
                                       Point<3>(5, 4, 0.5),   // corner
                                       Point<3>(1, 1, -1),    // face
                                       Point<3>(5, 2.5, -1),  // face
                                       Point<3>(0, 4, 0.5),   // edge
                                       Point<3>(1, 2.5, -1)}; // inside
  check("seeds on faces, edges and corners", box, on_boundary);

  check("one seed", box, {Point<3>(0, 2, -1)});

  // thin and needle-shaped boxes: the seeds and the images within the
  // first reach are collinear or coplanar (a 1D or 2D Delaunay
  // triangulation, which crashed before). Their extents are powers of two
  // times each other: the dyadic frame represents them exactly (it
  // rounds to 1e-12 of the largest extent, which a box 400 times thinner
  // than wide would see as 4e-10 of its volume).
  const BoundingBox<3> thin(
    std::make_pair(Point<3>(-32, -32, 0), Point<3>(32, 32, 0.25)));
  check("one seed in a thin box", thin, {Point<3>(1, -2, 0.125)});
  check("two seeds in a thin box",
        thin,
        {Point<3>(-10, 3, 0.1), Point<3>(12, -5, 0.1)});
  const BoundingBox<3> needle(
    std::make_pair(Point<3>(0, 0, 0), Point<3>(0.03125, 0.03125, 32)));
  check("one seed in a needle", needle, {Point<3>(0.01, 0.01, 7)});
  check("collinear seeds in a needle",
        needle,
        {Point<3>(0.015, 0.015, 3), Point<3>(0.015, 0.015, 17)});

  try
    {
      ssc::VoronoiDiagnostics diagnostics;
      ssc::compute_clipped_voronoi(box,
                                   {Point<3>(0, 2, -1), Point<3>(0, 2, -1)},
                                   false,
                                   diagnostics);
      deallog << "coinciding seeds: accepted (wrong)" << std::endl;
    }
  catch (const ExceptionBase &e)
    {
      deallog << "coinciding seeds: error" << std::endl;
    }
}
