#ifndef ssc_mesh_disk_fitting_map_h
#define ssc_mesh_disk_fitting_map_h

#include <deal.II/base/point.h>

#include <algorithm>
#include <array>

namespace ssc
{
  using namespace dealii;

  /**
   * A radial map of the (x, y) plane that takes the square |p|_inf <= a of a
   * Cartesian mesh onto the disk r <= a and blends back to the identity at
   * |p|_inf = 2a. Mesh lines on the square's boundary then follow the circle
   * r = a exactly at every refinement level (the map is applied through the
   * LayerManifold), so a punch of radius a sees a boundary that conforms to
   * its edge instead of a staircase of nodes inside it.
   *
   * Along a ray with |u|_inf = c for the unit direction u, a point at
   * distance rho goes to distance R(rho) = rho ((1 - t) c + t), with
   * t = clamp((rho c - a) / a, 0, 1): monotone, so the inverse is a 1D
   * bisection. a = 0 is the identity.
   *
   * With two semi-axes (a_x, a_y) the rectangle |x| <= a_x, |y| <= a_y goes
   * onto the ellipse of those semi-axes, by the same map in the scaled
   * coordinates (x / a_x, y / a_y): an elliptic excision's rim.
   */
  class DiskFittingMap
  {
  public:
    explicit DiskFittingMap(const double radius = 0)
      : DiskFittingMap(radius, radius)
    {}

    DiskFittingMap(const double semi_axis_x, const double semi_axis_y)
      : a(std::min(semi_axis_x, semi_axis_y))
      , scale{{semi_axis_x / a, semi_axis_y / a}}
    {
      if (a <= 0)
        scale = {{1., 1.}};
    }

    Point<2>
    forward(const Point<2> &p) const;

    Point<2>
    inverse(const Point<2> &q) const;

    /// The circle's radius, or the ellipse's short semi-axis.
    double
    radius() const
    {
      return a;
    }

  private:
    /// The radial stretch factor m: R = rho m(rho) along direction u.
    double
    stretch(const double rho, const double c) const;

    /// The map of the circle of radius a, and its inverse.
    Point<2>
    circle_forward(const Point<2> &p) const;

    Point<2>
    circle_inverse(const Point<2> &q) const;

    /// Applies the circle's map (radius a) to @p p / scale, times scale.
    Point<2>
    scaled(const Point<2> &p, const bool forwards) const;

    double                a;
    std::array<double, 2> scale;
  };
} // namespace ssc

#endif
