// A cut through a pre-tensioned thin plate against Griffith's crack
// (Inglis 1913, Griffith 1921): a plate of thickness 1 mm (neo-Hookean, E
// 1 MPa, nu 0.3) with the prestretch s = 1.001 (an eigenstrain of -1e-3),
// its sides on rollers (so that it carries the plane-stress equibiaxial
// pre-stress sigma = E (s - 1) / (1 - nu)), a 640 mm square cut through
// its whole thickness by an incision of length 2a = 8 mm along y at its
// centre. The lips of a crack in an infinite plate under sigma open to the
// ellipse u = (2 sigma / E) sqrt(a^2 - t^2) each side: the gap at the
// centre is 4 sigma a / E = 4 a (s - 1) / (1 - nu) and the wound's area
// pi a (gap / 2). The load is ramped with the prestretch fraction, the
// wound measured by measure_wound(). The plate is 80 cracks wide: a finite
// plate with held sides is stiffer than the infinite one (the extrapolated
// gap is 0.7 % short at 20 cracks, 0.3 % at 80); the linear elasticity of
// the reference is O(s - 1) = 0.1 % off. The gap converges as the cells
// along the cut shrink (the crack tips are singular): measured at 0.5,
// 0.25 and 0.125 mm cells, its observed order printed, and its Richardson
// extrapolation within 0.5 % of Griffith's (the area, which the coarse
// cells at the tips cut short, within 1 %). The same plate with a hole of
// diameter 2a excised (Incision::Shape::disc, the mesh lines fitted to its
// edge): the pre-stress released on the hole's edge moves it out by u_r =
// (1 + nu) sigma a / E (Lame), so that its area grows by (1 + u_r / a)^2 -
// 1, within 1 % on 0.25 mm cells, and the hole stays round.

#include <cmath>
#include <iomanip>
#include <iostream>
#include <sstream>

#include "pretensioned_plate.h"
#include "tests.h"

using namespace dealii;

namespace
{
  using pretensioned_plate::E;
  using pretensioned_plate::nu;
  constexpr double s = 1.001, a = 4, width = 640;

  /// The wound of the plate with cells of @p h mm along the cut, or of
  /// the hole of diameter 2a with @p hole.
  ssc::WoundShape
  cut_plate(const double h, const bool hole = false)
  {
    return pretensioned_plate::cut_plate(h, hole, s, a, width);
  }
} // namespace


int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  const double griffith_gap  = 4 * a * (s - 1) / (1 - nu);
  const double griffith_area = M_PI * a * griffith_gap / 2;
  deallog << "Griffith: gap " << std::setprecision(6) << griffith_gap
          << " mm, area " << griffith_area << " mm^2" << std::endl;
  std::vector<double> gaps, areas;
  for (const double h : {0.5, 0.25, 0.125})
    {
      const ssc::WoundShape wound = cut_plate(h);
      gaps.push_back(wound.gap_mm);
      areas.push_back(wound.area_mm2);
      std::ostringstream line;
      line << "cells " << h << " mm: gap / Griffith's " << std::setprecision(3)
           << wound.gap_mm / griffith_gap << ", area / Griffith's "
           << wound.area_mm2 / griffith_area << ", length "
           << std::setprecision(6) << wound.length_mm << " mm, orientation "
           << std::setprecision(3) << wound.orientation_deg << " degrees, "
           << wound.lips.size() << " lip points";
      deallog << line.str() << std::endl;
    }
  // the observed order of the last three and the extrapolation to h = 0
  const auto extrapolate = [](const std::vector<double> &v, double &order) {
    order = std::log2((v[1] - v[0]) / (v[2] - v[1]));
    return v[2] + (v[2] - v[1]) / (std::pow(2., order) - 1);
  };
  double             gap_order, area_order;
  const double       gap  = extrapolate(gaps, gap_order);
  const double       area = extrapolate(areas, area_order);
  std::ostringstream orders;
  orders << "observed orders: gap " << std::setprecision(1) << std::fixed
         << gap_order << ", area " << area_order;
  deallog << orders.str() << std::endl;
  deallog << "extrapolated gap within 0.5 % of Griffith's: "
          << (std::abs(gap / griffith_gap - 1) < 0.005 ? "yes" : "no")
          << std::endl;
  deallog << "extrapolated area within 1 % of Griffith's: "
          << (std::abs(area / griffith_area - 1) < 0.01 ? "yes" : "no")
          << std::endl;

  // the hole: its edge moves out by u_r = (1 + nu) sigma a / E (the
  // pre-stress released on it, Lame), its area grows by (1 + u_r / a)^2 - 1
  const double lame =
    100 * (std::pow(1 + (1 + nu) * (s - 1) / (1 - nu), 2) - 1);
  deallog << "Lame: hole area change " << std::setprecision(6) << lame << " %"
          << std::endl;
  for (const double h : {0.5, 0.25})
    {
      const ssc::WoundShape wound = cut_plate(h, true);
      std::ostringstream    line;
      line << "hole, cells " << h << " mm: area change / Lame's "
           << std::setprecision(3) << wound.area_change_pct / lame
           << ", aspect ratio " << std::setprecision(6) << wound.aspect_ratio
           << ", " << wound.lips.size() << " rim points";
      deallog << line.str() << std::endl;
      if (h == 0.25)
        deallog << "hole area change within 1 % of Lame's: "
                << (std::abs(wound.area_change_pct / lame - 1) < 0.01 ? "yes" :
                                                                        "no")
                << ", round within 1e-6: "
                << (std::abs(wound.aspect_ratio - 1) < 1e-6 ? "yes" : "no")
                << std::endl;
    }
}
