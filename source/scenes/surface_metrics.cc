#include <deal.II/base/exceptions.h>

#include <ssc/scenes/surface_metrics.h>

#include <algorithm>
#include <cmath>

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
  } // namespace


  SurfaceMetrics
  SurfaceMetrics::compute(const GridField &elevation,
                          const double     sigma,
                          const double     dimple_depth)
  {
    const unsigned int nx = elevation.x.size(), ny = elevation.y.size();
    AssertThrow(nx >= 3 && ny >= 3 && elevation.values.size() == nx * ny,
                dealii::ExcMessage("The elevation grid needs at least 3 x 3 "
                                   "points."));
    const double hx = elevation.x[1] - elevation.x[0];
    const double hy = elevation.y[1] - elevation.y[0];

    SurfaceMetrics metrics;
    metrics.trend = elevation;
    std::vector<double> weight(nx * ny, 1.);
    const auto          kernel_x = gaussian_kernel(sigma, hx);
    const auto          kernel_y = gaussian_kernel(sigma, hy);
    for (std::vector<double> *field : {&metrics.trend.values, &weight})
      {
        smooth_lines(*field, nx, 1, ny, nx, kernel_x);
        smooth_lines(*field, ny, nx, nx, 1, kernel_y);
      }
    for (unsigned int k = 0; k < nx * ny; ++k)
      metrics.trend.values[k] /= weight[k];

    metrics.max_elevation =
      *std::max_element(elevation.values.begin(), elevation.values.end());
    double sum = 0, square = 0, volume = 0;
    for (unsigned int j = 0; j < ny; ++j)
      for (unsigned int i = 0; i < nx; ++i)
        {
          const double u = elevation(i, j);
          const double r = u - metrics.trend(i, j);
          sum += u;
          square += r * r;
          // trapezoidal weights
          volume += u * hx * hy * ((i == 0 || i + 1 == nx) ? 0.5 : 1.) *
                    ((j == 0 || j + 1 == ny) ? 0.5 : 1.);
        }
    metrics.mean_elevation = sum / (nx * ny);
    metrics.roughness      = std::sqrt(square / (nx * ny));
    metrics.uplift_volume  = volume;

    for (unsigned int j = 1; j + 1 < ny; ++j)
      for (unsigned int i = 1; i + 1 < nx; ++i)
        {
          const auto residual = [&](const unsigned int a,
                                    const unsigned int b) {
            return elevation(a, b) - metrics.trend(a, b);
          };
          const double depth = -residual(i, j);
          if (depth < dimple_depth)
            continue;
          bool lowest = true;
          for (int dj = -1; dj <= 1 && lowest; ++dj)
            for (int di = -1; di <= 1 && lowest; ++di)
              if ((di != 0 || dj != 0) && -residual(i + di, j + dj) >= depth)
                lowest = false;
          if (lowest)
            metrics.dimples.push_back({elevation.x[i], elevation.y[j], depth});
        }
    return metrics;
  }


  nlohmann::ordered_json
  SurfaceMetrics::to_json() const
  {
    double mean_depth = 0, max_depth = 0;
    for (const Dimple &d : dimples)
      {
        mean_depth += d.depth / dimples.size();
        max_depth = std::max(max_depth, d.depth);
      }
    return {{"max_elevation_mm", max_elevation},
            {"mean_elevation_mm", mean_elevation},
            {"roughness_mm", roughness},
            {"dimples",
             {{"count", dimples.size()},
              {"mean_depth_mm", mean_depth},
              {"max_depth_mm", max_depth}}},
            {"uplift_volume_mm3", uplift_volume}};
  }
} // namespace ssc
