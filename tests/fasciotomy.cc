// A fasciotomy removes exactly the septa (by area-weighted centroid) and
// the skin ligaments within its radius of the site and nothing else: the
// microstructure built with the release equals the one built without it
// minus what lies inside; the lobule tessellation is untouched. Also: the
// lobule locator finds, for the centroid of every lobule, that lobule.

#include <algorithm>
#include <cmath>
#include <set>
#include <tuple>

#include <ssc/microstructure/lobule_locator.h>
#include <ssc/microstructure/microstructure.h>

#include "tests.h"

using namespace dealii;

namespace
{
  /// A septum by its layer and its two lobules; a ligament by its position.
  std::set<std::tuple<unsigned int, unsigned int, unsigned int>>
  septum_keys(const ssc::Microstructure &m)
  {
    std::set<std::tuple<unsigned int, unsigned int, unsigned int>> keys;
    for (const auto &s : m.septa())
      keys.insert({s.layer, s.lobules[0], s.lobules[1]});
    return keys;
  }

  std::set<std::pair<double, double>>
  ligament_keys(const ssc::Microstructure &m)
  {
    std::set<std::pair<double, double>> keys;
    for (const auto &l : m.ligaments())
      keys.insert({l.top[0], l.top[1]});
    return keys;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  ssc::LayerStack layers;
  layers.add_layer("skin", ssc::LayerKind::skin, "2", 0.02, 0.49, 1);
  layers.add_layer(
    "SAT", ssc::LayerKind::SAT, "4 + 0.05*x", 0.001, 0.49, 1, 1., 3., 1.5);
  layers.add_layer("SM", ssc::LayerKind::SM, "0.5", 0.06, 0.49, 1);
  layers.add_layer("DAT", ssc::LayerKind::DAT, "5", 0.001, 0.49, 1, 1., 6.);
  layers.add_layer("deep", ssc::LayerKind::deep, "5", 0.015, 0.49, 1);

  ssc::MicrostructureParameters parameters;
  parameters.lobules          = true;
  parameters.ligaments        = true;
  parameters.ligament_density = "4";
  parameters.lloyd_iterations = 5;
  ssc::Microstructure intact(layers, 30, 30, parameters);
  intact.build();

  parameters.fasciotomy.enabled = true;
  parameters.fasciotomy.centre  = Point<2>(2, -1);
  parameters.fasciotomy.radius  = 8;
  ssc::Microstructure released(layers, 30, 30, parameters);
  released.build();

  const ssc::Fasciotomy &cut          = parameters.fasciotomy;
  unsigned int           septa_inside = 0, ligaments_inside = 0;
  auto                   expected_septa     = septum_keys(intact);
  auto                   expected_ligaments = ligament_keys(intact);
  for (const auto &s : intact.septa())
    {
      const Point<3> c = ssc::Microstructure::centroid(s);
      if (cut.cuts(c[0], c[1]))
        {
          ++septa_inside;
          expected_septa.erase({s.layer, s.lobules[0], s.lobules[1]});
        }
    }
  for (const auto &l : intact.ligaments())
    if (cut.cuts(l.top[0], l.top[1]))
      {
        ++ligaments_inside;
        expected_ligaments.erase({l.top[0], l.top[1]});
      }
  deallog << "intact: " << intact.septa().size() << " septa, "
          << intact.ligaments().size()
          << " ligaments; inside the release: " << septa_inside << " septa, "
          << ligaments_inside << " ligaments" << std::endl;
  const auto statistics = released.fasciotomy_summary();
  deallog << "released: " << released.septa().size() << " septa, "
          << released.ligaments().size() << " ligaments; reported cut "
          << statistics["cut_septa"] << " septa, "
          << statistics["cut_ligaments"] << " ligaments" << std::endl;
  deallog << "the septa left are exactly those outside: "
          << (septum_keys(released) == expected_septa ? "yes" : "no")
          << std::endl;
  deallog << "the ligaments left are exactly those outside: "
          << (ligament_keys(released) == expected_ligaments ? "yes" : "no")
          << std::endl;
  deallog << "lobules untouched: "
          << (released.n_lobules() == intact.n_lobules() ? "yes" : "no")
          << std::endl;
  unsigned int triangles = 0;
  for (const auto &s : released.septa())
    triangles += s.triangles.size();
  deallog << "septa mesh rebuilt: "
          << (released.septa_mesh().n_active_cells() == triangles ? "yes" :
                                                                    "no")
          << std::endl;

  // the lobule of each lobule's centroid is that lobule (the centroids of
  // these convex cells lie inside them)
  for (const auto &layer : intact.lobule_layers())
    {
      const ssc::LobuleLocator locator(layers, layer);
      unsigned int             found = 0;
      for (unsigned int i = 0; i < layer.lobules.size(); ++i)
        found += locator.lobule_at(layer.lobules[i].centroid) == i;
      deallog << layers.layer(layer.layer).name << ": lobule locator finds "
              << found << " of " << layer.lobules.size()
              << " lobules at their centroid" << std::endl;
    }
}
