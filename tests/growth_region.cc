// Heterogeneous growth of the lobules (GrowthRegion, Growth/Lobule growth
// spread, Growing lobule fraction, Random seed) on the lobules of a
// 40 x 40 mm patch:
// - without spread and with every lobule growing, every lobule of the
//   selected layers has weight 1 and the other layers 0;
// - with spread s = 0.6 the weights are lognormal of mean 1: their mean is
//   1 and the standard deviation of ln w is s, each within three standard
//   errors of the sample (sqrt((e^{s^2} - 1) / n) and s / sqrt(2 n));
// - with fraction 0.3 the share of growing lobules is 0.3 within three
//   binomial standard errors, and the draws of the spread are the same as
//   with fraction 1 for the lobules that still grow (the draws do not
//   reshuffle each other);
// - the same seed draws the same weights, another seed others;
// - in an ellipsoid only the lobules with their centroid inside grow;
// - the weight at a lobule's centroid is that lobule's weight;
// - a septum's weight (the septa that grow with the fat) is the mean of
//   its two lobules' weights at their centroids, with spread and fraction
//   and in the ellipsoid, where the walls of the site's boundary grow half
//   as much.

#include <cmath>
#include <map>
#include <numeric>

#include <ssc/microstructure/microstructure.h>
#include <ssc/scenes/growth_region.h>

#include "tests.h"

using namespace dealii;

namespace
{
  /// The weight of every lobule of every layer, in the lobules' order.
  std::vector<double>
  weights_at_centroids(const ssc::GrowthRegion   &region,
                       const ssc::Microstructure &microstructure)
  {
    std::vector<double> w;
    for (const ssc::LayerLobules &layer : microstructure.lobule_layers())
      for (const ssc::Lobule &lobule : layer.lobules)
        w.push_back(region(lobule.centroid, lobule.layer));
    return w;
  }

  /// The septa whose weight is not the mean of their lobules' weights at
  /// the centroids.
  unsigned int
  wrong_septum_weights(const ssc::GrowthRegion   &region,
                       const ssc::Microstructure &microstructure)
  {
    std::map<unsigned int, const ssc::Lobule *> by_id;
    for (const ssc::LayerLobules &layer : microstructure.lobule_layers())
      for (const ssc::Lobule &lobule : layer.lobules)
        by_id[lobule.id] = &lobule;
    unsigned int wrong = 0;
    for (const ssc::Septum &septum : microstructure.septa())
      {
        double mean = 0;
        for (const unsigned int id : septum.lobules)
          mean += region(by_id.at(id)->centroid, septum.layer) / 2;
        wrong += std::abs(region.septum_weight(septum) - mean) > 1e-14;
      }
    return wrong;
  }

  const char *
  yes_no(const bool b)
  {
    return b ? "yes" : "no";
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  ssc::LayerStack layers;
  layers.add_layer("skin", ssc::LayerKind::skin, "1.5", 0.02, 0.49, 1);
  layers.add_layer("SAT", ssc::LayerKind::SAT, "4", 0.001, 0.49, 1, 1., 3.);
  layers.add_layer("SM", ssc::LayerKind::SM, "0.5", 0.06, 0.49, 1);
  layers.add_layer("DAT", ssc::LayerKind::DAT, "5", 0.001, 0.49, 1, 1., 6.);
  layers.add_layer("deep", ssc::LayerKind::deep, "5", 0.015, 0.49, 1);
  ssc::MicrostructureParameters parameters;
  parameters.lobules          = true;
  parameters.lloyd_iterations = 5;
  ssc::Microstructure microstructure(layers, 40, 40, parameters);
  microstructure.build();
  const unsigned int sat = layers.index_of("SAT", "test");

  ssc::GrowthParameters growth;
  growth.layers = {"SAT"};
  {
    const ssc::GrowthRegion region(layers, growth, &microstructure);
    unsigned int            n_sat = 0, wrong = 0;
    for (const ssc::LayerLobules &layer : microstructure.lobule_layers())
      for (const ssc::Lobule &lobule : layer.lobules)
        {
          const double expected = lobule.layer == sat ? 1. : 0.;
          n_sat += lobule.layer == sat;
          wrong += region(lobule.centroid, lobule.layer) != expected;
        }
    deallog << "uniform: " << region.lobule_weights().size() << " of " << n_sat
            << " SAT lobules grow, weights not 1 (SAT) or 0 (DAT): " << wrong
            << std::endl;
  }

  growth.lobule_growth_spread = 0.6;
  const ssc::GrowthRegion   spread(layers, growth, &microstructure);
  const std::vector<double> w    = spread.lobule_weights();
  const double              n    = w.size();
  const double              mean = std::accumulate(w.begin(), w.end(), 0.) / n;
  double                    log_mean = 0, log_square = 0;
  for (const double v : w)
    log_mean += std::log(v) / n;
  for (const double v : w)
    log_square += std::pow(std::log(v) - log_mean, 2) / (n - 1);
  const double s = growth.lobule_growth_spread;
  deallog << "spread 0.6: " << w.size() << " lobules; mean weight within "
          << "three standard errors of 1: "
          << yes_no(std::abs(mean - 1) <
                    3 * std::sqrt((std::exp(s * s) - 1) / n))
          << "; sd of ln w within three standard errors of 0.6: "
          << yes_no(std::abs(std::sqrt(log_square) - s) <
                    3 * s / std::sqrt(2 * n))
          << std::endl;

  growth.growing_lobule_fraction = 0.3;
  const ssc::GrowthRegion   partial(layers, growth, &microstructure);
  const std::vector<double> all = weights_at_centroids(spread, microstructure);
  const std::vector<double> some =
    weights_at_centroids(partial, microstructure);
  unsigned int growing = 0, changed = 0;
  for (unsigned int k = 0; k < all.size(); ++k)
    if (some[k] > 0)
      {
        ++growing;
        changed += some[k] != all[k];
      }
  const double share = growing / n;
  deallog << "fraction 0.3: growing share within three standard errors: "
          << yes_no(std::abs(share - 0.3) < 3 * std::sqrt(0.3 * 0.7 / n))
          << "; weights of the growing lobules as with fraction 1: "
          << yes_no(growing > 0 && changed == 0) << "; septum weights not "
          << "the mean of their lobules': "
          << wrong_septum_weights(partial, microstructure) << " of "
          << microstructure.septa().size() << std::endl;

  growth.growing_lobule_fraction = 1;
  const ssc::GrowthRegion same(layers, growth, &microstructure);
  growth.growth_seed = 2;
  const ssc::GrowthRegion other(layers, growth, &microstructure);
  deallog << "seed: same draws again " << yes_no(same.lobule_weights() == w)
          << ", another seed other draws "
          << yes_no(other.lobule_weights() != w) << std::endl;

  growth.lobule_growth_spread = 0;
  growth.shape                = ssc::GrowthRegionShape::ellipsoid;
  growth.centre               = Point<3>(0, 0, -3.5);
  growth.semi_axes            = Point<3>(8, 8, 3);
  const ssc::GrowthRegion site(layers, growth, &microstructure);
  unsigned int            inside = 0, mismatched = 0;
  for (const ssc::LayerLobules &layer : microstructure.lobule_layers())
    for (const ssc::Lobule &lobule : layer.lobules)
      {
        const bool grows =
          lobule.layer == sat && growth.contains(lobule.centroid);
        inside += grows;
        mismatched += site(lobule.centroid, lobule.layer) != (grows ? 1. : 0.);
      }
  std::map<double, unsigned int> septa_by_weight;
  for (const ssc::Septum &septum : microstructure.septa())
    ++septa_by_weight[site.septum_weight(septum)];
  deallog << "ellipsoid: " << site.lobule_weights().size()
          << " lobules grow, centroids inside " << inside
          << ", weights at the centroids wrong " << mismatched << std::endl;
  deallog << "ellipsoid: septa of weight";
  for (const auto &[weight, count] : septa_by_weight)
    deallog << " " << weight << ": " << count;
  deallog << "; not the mean of their lobules': "
          << wrong_septum_weights(site, microstructure) << std::endl;
}
