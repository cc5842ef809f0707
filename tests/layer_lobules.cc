// Lobules of adipose layers mapped to physical coordinates: on a stack whose
// SAT has a constant and whose DAT a variable (linear) thickness, the lobule
// volumes sum to the layer volume (relative 1e-10, the map is exact for
// linear thickness), every septum vertex lies inside its layer, every septum
// joins two distinct lobules of its layer and no pair twice, the same seed
// gives the same model (bit for bit) and another seed another model, and a
// cylindrical region keeps only lobules whose centroid lies inside it.

#include <cmath>
#include <iomanip>
#include <set>

#include <ssc/microstructure/lobules.h>

#include "tests.h"

using namespace dealii;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  ssc::LayerStack layers;
  layers.add_layer("skin", ssc::LayerKind::skin, "1.5", 0.02, 0.49, 1);
  layers.add_layer(
    "SAT", ssc::LayerKind::SAT, "3", 0.001, 0.49, 2, 1, 2.5, 1.5);
  layers.add_layer("SM", ssc::LayerKind::SM, "0.5", 0.06, 0.49, 1);
  layers.add_layer(
    "DAT", ssc::LayerKind::DAT, "4 + 0.05*x", 0.001, 0.49, 2, 1, 5, 0.5);
  layers.add_layer("deep", ssc::LayerKind::deep, "10", 0.015, 0.49, 2);

  ssc::MicrostructureParameters parameters;
  parameters.lobules              = true;
  parameters.lloyd_iterations     = 20;
  parameters.septum_triangle_size = 1;
  const BoundingBox<2> rectangle(
    std::make_pair(Point<2>(-15, -10), Point<2>(15, 10)));
  // exact layer volumes over the rectangle (30 x 20 mm)
  const double exact_volume[2] = {3. * 600., 4. * 600.};

  unsigned int first_id = 0;
  for (const unsigned int l : {1u, 3u})
    {
      const ssc::LayerLobules result =
        ssc::build_layer_lobules(layers, l, rectangle, parameters, first_id);
      double                 volume = 0;
      std::set<unsigned int> ids;
      for (const auto &lobule : result.lobules)
        {
          volume += lobule.volume;
          ids.insert(lobule.id);
        }
      unsigned int outside = 0, bad_pairs = 0;
      std::set<std::pair<unsigned int, unsigned int>> pairs;
      for (const auto &septum : result.septa)
        {
          for (const auto &triangle : septum.triangles)
            for (const auto &p : triangle)
              {
                const double top = -layers.depth_of_interface(l, p[0], p[1]);
                const double bottom =
                  -layers.depth_of_interface(l + 1, p[0], p[1]);
                outside += p[2] > top + 1e-9 || p[2] < bottom - 1e-9;
              }
          const auto [a, b] =
            std::make_pair(septum.lobules[0], septum.lobules[1]);
          bad_pairs += a == b || !ids.count(a) || !ids.count(b) ||
                       !pairs.insert({std::min(a, b), std::max(a, b)}).second ||
                       septum.layer != l;
        }
      deallog << layers.layer(l).name << ": " << result.lobules.size()
              << " lobules, " << result.septa.size() << " septa, first id "
              << result.lobules.front().id << std::endl;
      deallog << "  volume sum relative error below 1e-10: "
              << (std::abs(volume / exact_volume[l == 1 ? 0 : 1] - 1) < 1e-10 ?
                    "yes" :
                    "no")
              << "; region volume error below 1e-10: "
              << (std::abs(result.region_volume / exact_volume[l == 1 ? 0 : 1] -
                           1) < 1e-10 ?
                    "yes" :
                    "no")
              << std::endl;
      deallog << "  septum vertices outside the layer " << outside
              << ", septa with a bad lobule pair " << bad_pairs << std::endl;
      first_id += result.lobules.size();
    }

  // same seed, same model; another seed, another model
  const auto centroids = [&](const unsigned int seed) {
    ssc::MicrostructureParameters p = parameters;
    p.seed                          = seed;
    std::vector<Point<3>> c;
    for (const auto &lobule :
         ssc::build_layer_lobules(layers, 3, rectangle, p, 0).lobules)
      c.push_back(lobule.centroid);
    return c;
  };
  deallog << "same seed, identical centroids: "
          << (centroids(4) == centroids(4) ? "yes" : "no") << std::endl;
  deallog << "other seed, other centroids: "
          << (centroids(4) != centroids(5) ? "yes" : "no") << std::endl;

  ssc::MicrostructureParameters cylinder = parameters;
  cylinder.region.shape                  = ssc::RegionShape::cylinder;
  cylinder.region.centre                 = Point<2>(2, -1);
  cylinder.region.radius                 = 6;
  const ssc::LayerLobules in_cylinder    = ssc::build_layer_lobules(
    layers, 1, cylinder.region.bounding_rectangle(30, 20), cylinder, 0);
  unsigned int outside = 0;
  for (const auto &lobule : in_cylinder.lobules)
    outside += std::hypot(lobule.centroid[0] - 2, lobule.centroid[1] + 1) > 6;
  deallog << "cylinder: " << in_cylinder.lobules.size()
          << " lobules, centroids outside " << outside << std::endl;
}
