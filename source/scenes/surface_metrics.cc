#include <deal.II/base/exceptions.h>

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>
#include <utility>

#include <ssc/scenes/surface_metrics.h>

namespace ssc
{
  namespace
  {
    /// Gaussian smoothing along one grid direction: @p n points with
    /// @p stride between them, @p count lines of them, @p offset between
    /// lines; the kernel is cut at three standard deviations.
    void
    smooth_lines(std::vector<double>       &field,
                 const unsigned int         n,
                 const unsigned int         stride,
                 const unsigned int         count,
                 const unsigned int         offset,
                 const std::vector<double> &kernel)
    {
      const int           half = kernel.size() - 1;
      std::vector<double> line(n);
      for (unsigned int l = 0; l < count; ++l)
        {
          for (unsigned int i = 0; i < n; ++i)
            {
              double sum = 0;
              for (int k = -half; k <= half; ++k)
                {
                  const int m = static_cast<int>(i) + k;
                  if (m >= 0 && m < static_cast<int>(n))
                    sum += kernel[std::abs(k)] * field[l * offset + m * stride];
                }
              line[i] = sum;
            }
          for (unsigned int i = 0; i < n; ++i)
            field[l * offset + i * stride] = line[i];
        }
    }


    std::vector<double>
    gaussian_kernel(const double sigma, const double h)
    {
      const unsigned int  half = std::ceil(3. * sigma / h);
      std::vector<double> kernel(half + 1);
      for (unsigned int k = 0; k <= half; ++k)
        kernel[k] = std::exp(-0.5 * std::pow(k * h / sigma, 2));
      return kernel;
    }

    /// First and last index of the grid coordinates @p t with |t| <= @p
    /// half_width (all of them for half_width <= 0); at least two.
    std::pair<unsigned int, unsigned int>
    window_indices(const std::vector<double> &t, const double half_width)
    {
      unsigned int first = std::numeric_limits<unsigned int>::max(), last = 0;
      for (unsigned int i = 0; i < t.size(); ++i)
        if (half_width <= 0 || std::abs(t[i]) <= half_width * (1 + 1e-12))
          {
            first = std::min(first, i);
            last  = i;
          }
      AssertThrow(first != std::numeric_limits<unsigned int>::max() &&
                    last > first,
                  dealii::ExcMessage("The metrics window holds fewer than "
                                     "2 x 2 grid points."));
      return {first, last};
    }


    /// The least-squares plane c0 + c1 x + c2 y of @p elevation.
    dealii::Vector<double>
    least_squares_plane(const GridField &elevation)
    {
      const unsigned int nx = elevation.x.size(), ny = elevation.y.size();
      dealii::FullMatrix<double> normal(3, 3);
      dealii::Vector<double>     moments(3), plane(3);
      for (unsigned int j = 0; j < ny; ++j)
        for (unsigned int i = 0; i < nx; ++i)
          {
            const double basis[3] = {1., elevation.x[i], elevation.y[j]};
            for (unsigned int a = 0; a < 3; ++a)
              {
                moments(a) += basis[a] * elevation(i, j);
                for (unsigned int b = 0; b < 3; ++b)
                  normal(a, b) += basis[a] * basis[b];
              }
          }
      normal.gauss_jordan();
      normal.vmult(plane, moments);
      return plane;
    }


    /// The value of @p plane at the grid point (i, j) of @p elevation.
    double
    plane_at(const dealii::Vector<double> &plane,
             const GridField              &elevation,
             const unsigned int            i,
             const unsigned int            j)
    {
      return plane(0) + plane(1) * elevation.x[i] + plane(2) * elevation.y[j];
    }


    /// The trend: @p plane plus the normalised Gaussian filter (standard
    /// deviation @p sigma) of what departs from it.
    GridField
    smoothed_trend(const GridField              &elevation,
                   const dealii::Vector<double> &plane,
                   const double                  sigma,
                   const double                  hx,
                   const double                  hy)
    {
      const unsigned int nx = elevation.x.size(), ny = elevation.y.size();
      GridField          trend = elevation;
      for (unsigned int j = 0; j < ny; ++j)
        for (unsigned int i = 0; i < nx; ++i)
          trend.values[j * nx + i] -= plane_at(plane, elevation, i, j);
      std::vector<double> weight(nx * ny, 1.);
      const auto          kernel_x = gaussian_kernel(sigma, hx);
      const auto          kernel_y = gaussian_kernel(sigma, hy);
      for (std::vector<double> *field : {&trend.values, &weight})
        {
          smooth_lines(*field, nx, 1, ny, nx, kernel_x);
          smooth_lines(*field, ny, nx, nx, 1, kernel_y);
        }
      for (unsigned int j = 0; j < ny; ++j)
        for (unsigned int i = 0; i < nx; ++i)
          trend.values[j * nx + i] =
            trend.values[j * nx + i] / weight[j * nx + i] +
            plane_at(plane, elevation, i, j);
      return trend;
    }


    /// Sets the elevation, roughness and ISO 25178 height parameters and
    /// the uplift volume of @p metrics over its window.
    void
    compute_height_parameters(const GridField &elevation,
                              const double     hx,
                              const double     hy,
                              SurfaceMetrics  &metrics)
    {
      metrics.max_elevation = -std::numeric_limits<double>::max();
      metrics.Sp            = -std::numeric_limits<double>::max();
      metrics.Sv            = -std::numeric_limits<double>::max();
      double       sum = 0, square = 0, absolute = 0, volume = 0;
      unsigned int count = 0;
      for (unsigned int j = metrics.first_y; j <= metrics.last_y; ++j)
        {
          double profile_peak = -std::numeric_limits<double>::max();
          double profile_pit  = std::numeric_limits<double>::max();
          for (unsigned int i = metrics.first_x; i <= metrics.last_x; ++i)
            {
              const double u        = elevation(i, j);
              const double r        = u - metrics.trend(i, j);
              metrics.max_elevation = std::max(metrics.max_elevation, u);
              profile_peak          = std::max(profile_peak, r);
              profile_pit           = std::min(profile_pit, r);
              sum += u;
              square += r * r;
              absolute += std::abs(r);
              ++count;
              // trapezoidal weights on the window
              volume +=
                u * hx * hy *
                ((i == metrics.first_x || i == metrics.last_x) ? 0.5 : 1.) *
                ((j == metrics.first_y || j == metrics.last_y) ? 0.5 : 1.);
            }
          metrics.Sp = std::max(metrics.Sp, profile_peak);
          metrics.Sv = std::max(metrics.Sv, -profile_pit);
          metrics.Spm += profile_peak;
          metrics.Svm -= profile_pit;
        }
      const unsigned int n_profiles = metrics.last_y - metrics.first_y + 1;
      metrics.Spm /= n_profiles;
      metrics.Svm /= n_profiles;
      metrics.mean_elevation = sum / count;
      metrics.roughness      = std::sqrt(square / count);
      metrics.Sa             = absolute / count;
      metrics.uplift_volume  = volume;
    }


    /// Adds the dimples in the window of @p metrics to its list.
    void
    find_dimples(const GridField              &elevation,
                 const dealii::Vector<double> &plane,
                 const double                  dimple_depth,
                 SurfaceMetrics               &metrics)
    {
      const unsigned int nx = elevation.x.size(), ny = elevation.y.size();
      // A dimple is a depression of the skin itself: a local minimum of the
      // elevation (less the plane, so that a tilt does not hide it) that
      // lies at least dimple_depth below the trend. (Minima of elevation
      // minus trend would also count the noise along the trough that the
      // filter leaves around any dome narrower than a few sigma.)
      const auto untilted = [&](const unsigned int a, const unsigned int b) {
        return elevation(a, b) - plane_at(plane, elevation, a, b);
      };
      for (unsigned int j = std::max(metrics.first_y, 1u);
           j <= std::min(metrics.last_y, ny - 2);
           ++j)
        for (unsigned int i = std::max(metrics.first_x, 1u);
             i <= std::min(metrics.last_x, nx - 2);
             ++i)
          {
            const double depth = metrics.trend(i, j) - elevation(i, j);
            if (depth < dimple_depth)
              continue;
            bool lowest = true;
            for (int dj = -1; dj <= 1 && lowest; ++dj)
              for (int di = -1; di <= 1 && lowest; ++di)
                if ((di != 0 || dj != 0) &&
                    untilted(i + di, j + dj) <= untilted(i, j))
                  lowest = false;
            if (lowest)
              metrics.dimples.push_back(
                {elevation.x[i], elevation.y[j], depth});
          }
    }
  } // namespace


  SurfaceMetrics
  SurfaceMetrics::compute(const GridField &elevation,
                          const double     sigma,
                          const double     dimple_depth,
                          const double     half_width)
  {
    const unsigned int nx = elevation.x.size(), ny = elevation.y.size();
    AssertThrow(nx >= 3 && ny >= 3 && elevation.values.size() == nx * ny,
                dealii::ExcMessage("The elevation grid needs at least 3 x 3 "
                                   "points."));
    const double hx = elevation.x[1] - elevation.x[0];
    const double hy = elevation.y[1] - elevation.y[0];

    // The trend: the least-squares plane plus the Gaussian filter of what
    // departs from it, so that a tilt of the whole surface (a layer
    // thickening across the patch) does not leave a residual at the edges.
    const dealii::Vector<double> plane = least_squares_plane(elevation);

    SurfaceMetrics metrics;
    metrics.trend = smoothed_trend(elevation, plane, sigma, hx, hy);

    // the window of the metrics
    std::tie(metrics.first_x, metrics.last_x) =
      window_indices(elevation.x, half_width);
    std::tie(metrics.first_y, metrics.last_y) =
      window_indices(elevation.y, half_width);

    compute_height_parameters(elevation, hx, hy, metrics);
    find_dimples(elevation, plane, dimple_depth, metrics);
    return metrics;
  }


  namespace
  {
    /// Count, mean and largest depth of @p dimples.
    nlohmann::ordered_json
    dimples_json(const std::vector<Dimple> &dimples)
    {
      double mean_depth = 0, max_depth = 0;
      for (const Dimple &d : dimples)
        {
          mean_depth += d.depth / dimples.size();
          max_depth = std::max(max_depth, d.depth);
        }
      return {{"count", dimples.size()},
              {"mean_depth_mm", mean_depth},
              {"max_depth_mm", max_depth}};
    }
  } // namespace


  nlohmann::ordered_json
  SurfaceMetrics::to_json() const
  {
    return {{"max_elevation_mm", max_elevation},
            {"mean_elevation_mm", mean_elevation},
            {"roughness_mm", roughness},
            {"dimples", dimples_json(dimples)},
            {"uplift_volume_mm3", uplift_volume}};
  }


  nlohmann::ordered_json
  SurfaceMetrics::surface_json() const
  {
    return {{"Sa_mm", Sa},
            {"Sq_mm", roughness},
            {"Sp_mm", Sp},
            {"Sv_mm", Sv},
            {"Sz_mm", Sz()},
            {"Spm_mm", Spm},
            {"Svm_mm", Svm},
            {"dimples", dimples_json(dimples)}};
  }
} // namespace ssc
