#include <deal.II/base/exceptions.h>
#include <deal.II/base/function_parser.h>
#include <deal.II/base/quadrature_lib.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <sstream>

#include <ssc/base/surface_expression.h>
#include <ssc/microstructure/ligaments.h>

namespace ssc
{
  namespace
  {
    /// Indices of the layers whose top and bottom bound the ligaments.
    std::pair<unsigned int, unsigned int>
    ligament_interfaces(const LayerStack &layers, const LigamentTarget target)
    {
      unsigned int top = 0;
      while (top < layers.n_layers() &&
             layers.layer(top).kind == LayerKind::skin)
        ++top;
      AssertThrow(top > 0 && top < layers.n_layers(),
                  ExcMessage(
                    "Microstructure/Ligaments/Enabled: skin ligaments need "
                    "a layer of kind skin at the top of the stack "
                    "and layers below it."));
      const LayerKind wanted =
        target == LigamentTarget::SM ? LayerKind::SM : LayerKind::deep;
      for (unsigned int l = top; l < layers.n_layers(); ++l)
        if (layers.layer(l).kind == wanted)
          {
            AssertThrow(l > top,
                        ExcMessage("Microstructure/Ligaments/Target: the "
                                   "target layer lies directly under the "
                                   "skin, so the ligaments have no length."));
            return {top, l};
          }
      AssertThrow(false,
                  ExcMessage(std::string("Microstructure/Ligaments/Target = ") +
                             (target == LigamentTarget::SM ? "SM" : "deep") +
                             ": there is no layer of that kind below the "
                             "skin."));
      return {0, 0};
    }


    /// Whether a ligament at (x, y) is drawn: anywhere in the rectangle with
    /// a Realisation half width (the region cuts them afterwards), only
    /// inside the region of interest otherwise.
    bool
    drawn_at(const MicrostructureParameters &parameters,
             const double                    x,
             const double                    y)
    {
      return parameters.region.realisation_half_width > 0 ||
             parameters.region.contains(x, y);
    }


    /// Tilts each ligament of @p ligaments about its top by an angle from
    /// the vertical drawn from the normal distribution of the parameters
    /// (cut to [0, 75] degrees) and a uniform azimuth, and moves its bottom
    /// to where the tilted line meets the interface @p bottom (a fixed
    /// point iteration on the interface's depth, which converges for
    /// interface slopes below the cotangent of the angle). A line that
    /// would leave @p rectangle draws its azimuth again. Draws from a
    /// generator of its own, so that the positions do not depend on the
    /// inclination.
    void
    incline(std::vector<Ligament>          &ligaments,
            const LayerStack               &layers,
            const unsigned int              bottom,
            const BoundingBox<2>           &rectangle,
            const MicrostructureParameters &parameters)
    {
      const double mean   = parameters.ligament_inclination * M_PI / 180;
      const double spread = parameters.ligament_inclination_spread * M_PI / 180;
      if (mean == 0 && spread == 0)
        return;
      std::seed_seq                    seed_sequence{parameters.seed, 2000003u};
      std::mt19937                     generator(seed_sequence);
      std::normal_distribution<double> normal(mean, spread);
      std::uniform_real_distribution<double> uniform(0., 2 * M_PI);
      for (Ligament &ligament : ligaments)
        {
          double angle = normal(generator);
          while (angle < 0 || angle > 75 * M_PI / 180)
            angle = normal(generator);
          const Point<3> top = ligament.top;
          // where the line at @p azimuth meets the interface
          const auto end_at = [&](const double azimuth) {
            const Tensor<1, 2> direction(
              {std::cos(azimuth), std::sin(azimuth)});
            Point<2> end(top[0], top[1]);
            double   depth = -ligament.bottom[2];
            for (unsigned int k = 0; k < 50; ++k)
              {
                end = Point<2>(top[0], top[1]) +
                      (depth + top[2]) * std::tan(angle) * direction;
                const double next =
                  layers.depth_of_interface(bottom, end[0], end[1]);
                const bool converged = std::abs(next - depth) < 1e-10;
                depth                = next;
                if (converged)
                  break;
              }
            return Point<3>(end[0], end[1], -depth);
          };
          // near the rectangle's sides, azimuths are drawn again until the
          // line stays inside (the ligament stays vertical if none does)
          for (unsigned int attempt = 0; attempt < 64; ++attempt)
            {
              const Point<3> end = end_at(uniform(generator));
              if (rectangle.point_inside(Point<2>(end[0], end[1])))
                {
                  ligament.bottom = end;
                  break;
                }
            }
        }
    }
  } // namespace


  LigamentDensity::LigamentDensity(const BoundingBox<2>           &rectangle,
                                   const MicrostructureParameters &parameters)
    : density(parse_surface_expression(parameters.ligament_density,
                                       "Microstructure/Ligaments/Density"))
  {
    // Expected count (per cm^2 = per 100 mm^2) and the density's maximum,
    // by Gauss quadrature over the region's rectangle.
    const Point<2>    &lo = rectangle.get_boundary_points().first;
    const Point<2>    &hi = rectangle.get_boundary_points().second;
    const unsigned int n  = 32;
    const QGauss<2>    gauss(3);
    const double       hx = (hi[0] - lo[0]) / n, hy = (hi[1] - lo[1]) / n;
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = 0; j < n; ++j)
        for (unsigned int q = 0; q <= gauss.size(); ++q)
          {
            // the Gauss points, then the cell corner (for the maximum)
            const Point<2> local =
              q < gauss.size() ? gauss.point(q) : Point<2>();
            const Point<2> p(lo[0] + (i + local[0]) * hx,
                             lo[1] + (j + local[1]) * hy);
            const double   rho = density->value(p);
            if (!(rho >= 0 && std::isfinite(rho)))
              {
                std::ostringstream message;
                message << "Microstructure/Ligaments/Density = '"
                        << parameters.ligament_density << "' is " << rho
                        << " per cm^2 at (x, y) = (" << p[0] << ", " << p[1]
                        << "): it must be finite and non-negative.";
                AssertThrow(false, ExcMessage(message.str()));
              }
            maximum = std::max(maximum, rho);
            if (q < gauss.size() && drawn_at(parameters, p[0], p[1]))
              expected += gauss.weight(q) * hx * hy * rho / 100.;
          }
  }


  std::vector<Ligament>
  place_ligaments(const LayerStack               &layers,
                  const BoundingBox<2>           &rectangle,
                  const MicrostructureParameters &parameters)
  {
    const auto [top, bottom] =
      ligament_interfaces(layers, parameters.ligament_target);
    const LigamentDensity density(rectangle, parameters);
    const unsigned int    count = std::round(density.expected);
    std::vector<Ligament> ligaments;
    if (count == 0)
      return ligaments;
    const Point<2> &lo = rectangle.get_boundary_points().first;
    const Point<2> &hi = rectangle.get_boundary_points().second;

    std::seed_seq seed_sequence{parameters.seed, 1000003u};
    std::mt19937  generator(seed_sequence);
    std::uniform_real_distribution<double> uniform(0., 1.);
    // the density may exceed the sampled maximum between sample points
    const double  bound    = 1.05 * density.maximum;
    unsigned long attempts = 0;
    while (ligaments.size() < count)
      {
        AssertThrow(++attempts < 1000ul * count + 100000ul,
                    ExcMessage("Microstructure/Ligaments: could not place "
                               "the ligaments (is the density zero inside "
                               "the region of interest?)."));
        const double x = lo[0] + uniform(generator) * (hi[0] - lo[0]);
        const double y = lo[1] + uniform(generator) * (hi[1] - lo[1]);
        const double u = uniform(generator);
        if (!drawn_at(parameters, x, y) ||
            u * bound > density.density->value(Point<2>(x, y)))
          continue;
        ligaments.push_back(
          {Point<3>(x, y, -layers.depth_of_interface(top, x, y)),
           Point<3>(x, y, -layers.depth_of_interface(bottom, x, y))});
      }
    incline(ligaments, layers, bottom, rectangle, parameters);
    // drawn in the whole rectangle: the region cuts the realisation
    const auto outside = [&](const Ligament &ligament) {
      return !parameters.region.contains(ligament.top[0], ligament.top[1]);
    };
    ligaments.erase(std::remove_if(ligaments.begin(), ligaments.end(), outside),
                    ligaments.end());
    return ligaments;
  }
} // namespace ssc
