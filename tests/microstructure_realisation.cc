// Microstructure/Region of interest/Realisation half width: with it, a
// small and a large cylindrical region cut one realisation (the lobules
// and ligaments of the small region are exactly those of the large one
// that lie in the small one); without it, each region draws its own. A
// half width that does not hold the region is refused.

#include <algorithm>
#include <vector>

#include <ssc/microstructure/microstructure.h>

#include "tests.h"

using namespace dealii;

namespace
{
  struct Realisation
  {
    std::vector<Point<3>> lobule_centroids;
    std::vector<Point<3>> ligament_tops;
  };

  Realisation
  build(const ssc::LayerStack &layers,
        const double           radius,
        const double           half_width)
  {
    ssc::MicrostructureParameters parameters;
    parameters.lobules                       = true;
    parameters.ligaments                     = true;
    parameters.ligament_density              = "4";
    parameters.lloyd_iterations              = 10;
    parameters.septum_triangle_size          = 2;
    parameters.region.shape                  = ssc::RegionShape::cylinder;
    parameters.region.radius                 = radius;
    parameters.region.realisation_half_width = half_width;
    ssc::Microstructure microstructure(layers, 60, 60, parameters);
    microstructure.build({}, {});
    Realisation result;
    for (const auto &layer : microstructure.lobule_layers())
      for (const auto &lobule : layer.lobules)
        result.lobule_centroids.push_back(lobule.centroid);
    for (const auto &ligament : microstructure.ligaments())
      result.ligament_tops.push_back(ligament.top);
    return result;
  }

  /// Whether @p small is exactly the part of @p large within @p radius of
  /// the axis (the same points, to round-off).
  bool
  is_cut_of(const std::vector<Point<3>> &small,
            const std::vector<Point<3>> &large,
            const double                 radius)
  {
    std::vector<Point<3>> inside;
    for (const auto &p : large)
      if (p[0] * p[0] + p[1] * p[1] <= radius * radius)
        inside.push_back(p);
    if (inside.size() != small.size())
      return false;
    return std::all_of(small.begin(), small.end(), [&](const Point<3> &p) {
      return std::any_of(inside.begin(), inside.end(), [&](const Point<3> &q) {
        return p.distance(q) < 1e-9;
      });
    });
  }
} // namespace


int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  ssc::LayerStack layers;
  layers.add_layer("skin", ssc::LayerKind::skin, "1.2", 0.02, 0.49, 1);
  layers.add_layer(
    "SAT", ssc::LayerKind::SAT, "2.5", 0.001, 0.49, 2, 1, 3, 1.2);
  layers.add_layer("SM", ssc::LayerKind::SM, "0.4", 0.06, 0.49, 1);
  layers.add_layer("DAT", ssc::LayerKind::DAT, "2", 0.001, 0.49, 2, 1, 8, 0.35);
  layers.add_layer("deep", ssc::LayerKind::deep, "10", 0.015, 0.49, 2);

  for (const double half_width : {20., 0.})
    {
      const Realisation small = build(layers, 8, half_width);
      const Realisation large = build(layers, 15, half_width);
      deallog << "Realisation half width " << half_width << ": "
              << small.lobule_centroids.size() << " and "
              << large.lobule_centroids.size()
              << " lobules in radii 8 and 15 mm, " << small.ligament_tops.size()
              << " and " << large.ligament_tops.size()
              << " ligaments; the small "
              << "region is a cut of the large one: lobules "
              << (is_cut_of(small.lobule_centroids, large.lobule_centroids, 8) ?
                    "yes" :
                    "no")
              << ", ligaments "
              << (is_cut_of(small.ligament_tops, large.ligament_tops, 8) ?
                    "yes" :
                    "no")
              << std::endl;
    }

  try
    {
      build(layers, 15, 10);
      deallog << "a half width smaller than the region: accepted" << std::endl;
    }
  catch (const ExceptionBase &)
    {
      deallog << "a half width smaller than the region: refused" << std::endl;
    }
}
