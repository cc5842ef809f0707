#include <algorithm>
#include <cmath>

#include <ssc/mesh/disk_fitting_map.h>

namespace ssc
{
  double
  DiskFittingMap::stretch(const double rho, const double c) const
  {
    const double t = std::clamp((rho * c - a) / a, 0., 1.);
    return (1. - t) * c + t;
  }


  Point<2>
  DiskFittingMap::forward(const Point<2> &p) const
  {
    return scaled(p, true);
  }


  Point<2>
  DiskFittingMap::inverse(const Point<2> &q) const
  {
    return scaled(q, false);
  }


  Point<2>
  DiskFittingMap::scaled(const Point<2> &x, const bool forwards) const
  {
    if (a <= 0)
      return x;
    const Point<2> p(x[0] / scale[0], x[1] / scale[1]);
    const Point<2> image = forwards ? circle_forward(p) : circle_inverse(p);
    return Point<2>(image[0] * scale[0], image[1] * scale[1]);
  }


  Point<2>
  DiskFittingMap::circle_forward(const Point<2> &p) const
  {
    const double rho = p.norm();
    if (a <= 0 || rho == 0)
      return p;
    const double c = std::max(std::abs(p[0]), std::abs(p[1])) / rho;
    return p * stretch(rho, c);
  }


  Point<2>
  DiskFittingMap::circle_inverse(const Point<2> &q) const
  {
    const double R = q.norm();
    if (a <= 0 || R == 0)
      return q;
    const double c = std::max(std::abs(q[0]), std::abs(q[1])) / R;
    if (R <= a) // inside the disk: R = rho c
      return q / c;
    if (R >= 2 * a / c) // outside the blend: identity
      return q;
    // blend zone: bisection on R(rho) = rho m(rho), rho in [a/c, 2a/c]
    double lo = a / c, hi = 2 * a / c;
    for (unsigned int i = 0; i < 100 && hi - lo > 1e-15 * hi; ++i)
      {
        const double mid                      = 0.5 * (lo + hi);
        (mid * stretch(mid, c) < R ? lo : hi) = mid;
      }
    const double rho = 0.5 * (lo + hi);
    return q * (rho / R);
  }
} // namespace ssc
