// Surface metrics of the growth scenes on synthetic elevations:
// - a constant lift c plus an egg-crate relief A cos(k x) cos(k y) of
//   wavelength 2 mm (much shorter than the 3 mm trend filter): the trend
//   is c (to the filter's attenuation exp(-sigma^2 k^2) ~ 1e-39), the
//   roughness is the relief's RMS A/2, the mean and max elevation are c and
//   c + A, the uplift volume is c times the area, and the dimples are the
//   relief's minima (-A where one cosine is 1 and the other -1) inside the
//   grid, counted exactly; Sa, Sp, Sv, Sz and Svm (ISO 25178 and the
//   profile mean of the clinical scans) are those of the relief sampled on
//   the grid;
// - the same relief on a tilted plane, measured in a central window: the
//   plane belongs to the trend (the roughness stays A/2, the mean c), and
//   the dimples are the minima in the window, edges included (84 of the
//   169 integer points of [-6, 6]^2 have x + y odd);
// - a Gaussian dome of standard deviation 8 mm (the smooth swelling of a
//   deep injection), wider than the filter, has no dimples; its residual
//   at the centre is the closed form sigma^2 / (W^2 + sigma^2). (A dome as
//   narrow as the filter leaves a ring below its trend: relief, by
//   definition.)

#include <cmath>

#include <ssc/scenes/surface_metrics.h>

#include "tests.h"

using namespace dealii;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  const double   c = 0.7, A = 0.05, k = M_PI, L = 10, h = 0.25;
  ssc::GridField grid;
  for (double x = -L; x <= L + 1e-9; x += h)
    grid.x.push_back(x);
  grid.y               = grid.x;
  const unsigned int n = grid.x.size();
  grid.values.resize(n * n);
  unsigned int minima = 0;
  for (unsigned int j = 0; j < n; ++j)
    for (unsigned int i = 0; i < n; ++i)
      {
        const double x = grid.x[i], y = grid.y[j];
        grid.values[j * n + i] = c + A * std::cos(k * x) * std::cos(k * y);
        // minima: x, y integers of different parity, inside the grid
        const bool inside = i > 0 && j > 0 && i + 1 < n && j + 1 < n;
        const long ix = std::lround(x), iy = std::lround(y);
        if (inside && std::abs(x - ix) < 1e-9 && std::abs(y - iy) < 1e-9 &&
            (ix + iy) % 2 != 0)
          ++minima;
      }
  const ssc::SurfaceMetrics relief =
    ssc::SurfaceMetrics::compute(grid, 3., 0.01);
  // the discrete RMS of the relief over the grid nodes
  double square = 0;
  for (unsigned int j = 0; j < n; ++j)
    for (unsigned int i = 0; i < n; ++i)
      square += std::pow(grid.values[j * n + i] - c, 2);
  const double rms = std::sqrt(square / (n * n));
  deallog << "relief: roughness / (A/2) " << std::setprecision(4)
          << relief.roughness / (A / 2) << ", discrete RMS / (A/2) "
          << rms / (A / 2) << std::endl;
  deallog << "relief: mean " << relief.mean_elevation << " (c " << c
          << "), max " << relief.max_elevation << " (c + A " << c + A
          << "), uplift volume / (c area) "
          << relief.uplift_volume / (c * 4 * L * L) << std::endl;
  double deepest = 0, shallowest = 1;
  for (const auto &d : relief.dimples)
    {
      deepest    = std::max(deepest, d.depth);
      shallowest = std::min(shallowest, d.depth);
    }
  deallog << "relief: " << relief.dimples.size() << " dimples (expected "
          << minima << "), depths " << shallowest << " to " << deepest << " (A "
          << A << ")" << std::endl;

  // ISO 25178 parameters of the relief, against those of the relief
  // itself sampled on the grid (the trend being c): Sa the mean of
  // A |cos kx cos ky| ((2/pi)^2 A = 0.405 A in the continuum, 0.364 A on
  // the 0.25 mm samples), Sp = Sv = A at the integer points, Sz = 2 A; Svm
  // the mean over the x-profiles y = y_j of their deepest valley
  // A |cos k y_j|
  double sample_Sa = 0, sample_Svm = 0;
  for (unsigned int j = 0; j < n; ++j)
    {
      double pit = 0;
      for (unsigned int i = 0; i < n; ++i)
        {
          const double r = grid.values[j * n + i] - c;
          sample_Sa += std::abs(r) / (n * n);
          pit = std::min(pit, r);
        }
      sample_Svm -= pit / n;
    }
  deallog << "relief: Sa / sampled " << relief.Sa / sample_Sa
          << ", sampled Sa / continuum (2/pi)^2 A "
          << sample_Sa / (4 / M_PI / M_PI * A) << std::endl;
  deallog << "relief: Sp / A " << relief.Sp / A << ", Sv / A " << relief.Sv / A
          << ", Sz / 2A "
          << relief.surface_json()["Sz_mm"].get<double>() / (2 * A)
          << ", Svm / sampled " << relief.Svm / sample_Svm << ", Spm / Svm "
          << relief.Spm / relief.Svm << ", Sq / (A/2) "
          << relief.surface_json()["Sq_mm"].get<double>() / (A / 2)
          << std::endl;

  // the same relief on a tilted surface, measured in the central window
  // |x|, |y| <= 6 mm: the plane is part of the trend, the relief is not
  ssc::GridField tilted = grid;
  for (unsigned int j = 0; j < n; ++j)
    for (unsigned int i = 0; i < n; ++i)
      tilted.values[j * n + i] += 0.1 * grid.x[i] - 0.05 * grid.y[j];
  const ssc::SurfaceMetrics tilt =
    ssc::SurfaceMetrics::compute(tilted, 3., 0.01, 6.);
  deallog << "tilted relief in the window: roughness / (A/2) "
          << tilt.roughness / (A / 2) << ", mean " << tilt.mean_elevation
          << ", dimples " << tilt.dimples.size() << std::endl;

  for (unsigned int j = 0; j < n; ++j)
    for (unsigned int i = 0; i < n; ++i)
      grid.values[j * n + i] =
        std::exp(-(std::pow(grid.x[i], 2) + std::pow(grid.y[j], 2)) / 128.);
  const ssc::SurfaceMetrics dome = ssc::SurfaceMetrics::compute(grid, 3., 0.01);
  // the filtered Gaussian is a Gaussian of variance W^2 + sigma^2 and
  // amplitude W^2 / (W^2 + sigma^2): the residual at the centre is
  // sigma^2 / (W^2 + sigma^2) = 9/73
  const unsigned int centre = (n / 2) * n + n / 2;
  deallog << "dome: max " << dome.max_elevation << ", residual at the centre "
          << grid.values[centre] - dome.trend.values[centre]
          << " (exact 9/73 = " << 9. / 73. << "), roughness " << dome.roughness
          << ", dimples " << dome.dimples.size() << std::endl;
  deallog << "dome: centre residual within 3 % of the closed form (the "
             "kernel is cut at 3 sigma): "
          << (std::abs((grid.values[centre] - dome.trend.values[centre]) /
                         (9. / 73.) -
                       1.) < 0.03 ?
                "yes" :
                "no")
          << std::endl;
}
