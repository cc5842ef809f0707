// Skin ligaments: their number is the density integrated over the region
// (per cm^2), a linear density gradient puts proportionally more of them
// where the density is higher, every ligament runs vertically from the
// bottom of the skin to the top of the target layer (SM or deep, whose
// depth varies here), and the same seed places them identically; oblique
// ligaments (Inclination) keep their tops, end on the target layer and
// have the angles and uniform azimuths asked for.

#include <cmath>

#include <ssc/microstructure/ligaments.h>

#include "tests.h"

using namespace dealii;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  ssc::LayerStack layers;
  layers.add_layer("skin", ssc::LayerKind::skin, "2", 0.02, 0.49, 1);
  layers.add_layer("SAT", ssc::LayerKind::SAT, "5 + 0.05*y", 0.001, 0.49, 1);
  layers.add_layer("SM", ssc::LayerKind::SM, "0.5", 0.06, 0.49, 1);
  layers.add_layer("DAT", ssc::LayerKind::DAT, "3", 0.001, 0.49, 1);
  layers.add_layer("deep", ssc::LayerKind::deep, "10", 0.015, 0.49, 1);

  ssc::MicrostructureParameters parameters;
  parameters.ligaments = true;
  // 1 to 9 per cm^2 across x in [-40, 40]: 5 per cm^2 on average over
  // 80 x 60 mm = 48 cm^2, i.e. 240 ligaments
  parameters.ligament_density = "5 + 0.1*x";
  const BoundingBox<2> patch(
    std::make_pair(Point<2>(-40, -30), Point<2>(40, 30)));

  for (const auto target : {ssc::LigamentTarget::SM, ssc::LigamentTarget::deep})
    {
      parameters.ligament_target = target;
      const auto   ligaments = ssc::place_ligaments(layers, patch, parameters);
      unsigned int right = 0, off_interface = 0, not_vertical = 0;
      for (const auto &l : ligaments)
        {
          right += l.top[0] > 0;
          const double x = l.top[0], y = l.top[1];
          off_interface +=
            std::abs(l.top[2] + layers.depth_of_interface(1, x, y)) > 1e-12;
          const unsigned int bottom = target == ssc::LigamentTarget::SM ? 2 : 4;
          off_interface +=
            std::abs(l.bottom[2] + layers.depth_of_interface(bottom, x, y)) >
            1e-12;
          not_vertical += l.bottom[0] != x || l.bottom[1] != y;
        }
      deallog << (target == ssc::LigamentTarget::SM ? "to SM" : "to deep")
              << ": " << ligaments.size() << " ligaments (expected 240), "
              << "endpoints off their interface " << off_interface
              << ", not vertical " << not_vertical << std::endl;
      // expected share on x > 0: int_0^40 (5 + 0.1 x) / int_-40^40 = 0.7
      const double share = double(right) / ligaments.size();
      deallog << "  share on the denser half within 0.7 +- 0.06: "
              << (std::abs(share - 0.7) < 0.06 ? "yes" : "no") << std::endl;
    }
  const auto first  = ssc::place_ligaments(layers, patch, parameters);
  const auto second = ssc::place_ligaments(layers, patch, parameters);
  bool       same   = first.size() == second.size();
  for (unsigned int i = 0; same && i < first.size(); ++i)
    same = first[i].top == second[i].top && first[i].bottom == second[i].bottom;
  deallog << "same seed, same ligaments: " << (same ? "yes" : "no")
          << std::endl;

  // Oblique ligaments to the SM (whose depth varies with y): the tops stay
  // where they were placed; every bottom lies on the SM's top, at the
  // drawn angle from the vertical (measured from the end points); the
  // angles have the mean and standard deviation asked for (45 +- 10
  // degrees, cut far out in the tails: within three standard errors), and
  // the azimuths cover the circle (mean resultant length of n uniform
  // directions ~ 1/sqrt(n)).
  parameters.ligament_target             = ssc::LigamentTarget::SM;
  parameters.ligament_inclination        = 45;
  parameters.ligament_inclination_spread = 10;
  const auto   oblique = ssc::place_ligaments(layers, patch, parameters);
  unsigned int moved = 0, off_sm = 0, outside = 0;
  double       mean = 0, square = 0;
  Tensor<1, 2> resultant;
  for (unsigned int i = 0; i < oblique.size(); ++i)
    {
      const auto &l = oblique[i];
      moved += l.top != first[i].top;
      off_sm +=
        std::abs(l.bottom[2] +
                 layers.depth_of_interface(2, l.bottom[0], l.bottom[1])) > 1e-8;
      outside += !patch.point_inside(Point<2>(l.bottom[0], l.bottom[1]));
      const Tensor<1, 3> axis    = l.bottom - l.top;
      const double       lateral = std::hypot(axis[0], axis[1]);
      const double       angle   = std::atan2(lateral, -axis[2]) * 180 / M_PI;
      mean += angle / oblique.size();
      square += angle * angle / oblique.size();
      resultant += Tensor<1, 2>({axis[0] / lateral, axis[1] / lateral}) /
                   double(oblique.size());
    }
  const double n = oblique.size(), sd = std::sqrt(square - mean * mean);
  deallog << "oblique: " << oblique.size() << " ligaments, tops moved " << moved
          << ", bottoms off the SM " << off_sm << ", bottoms outside the patch "
          << outside << std::endl;
  deallog << "  mean angle within 3 standard errors of 45 degrees: "
          << (std::abs(mean - 45) < 3 * 10 / std::sqrt(n) ? "yes" : "no")
          << ", standard deviation within 3 standard errors of 10: "
          << (std::abs(sd - 10) < 3 * 10 / std::sqrt(2 * n) ? "yes" : "no")
          << ", azimuths' mean resultant below 3/sqrt(n): "
          << (resultant.norm() < 3 / std::sqrt(n) ? "yes" : "no") << std::endl;
}
