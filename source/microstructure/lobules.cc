#include <deal.II/base/exceptions.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/timer.h>

#include <cmath>
#include <random>
#include <sstream>

#include <ssc/microstructure/lobules.h>

namespace ssc
{
  namespace
  {
    /**
     * The map from the reference box [x0, x1] x [y0, y1] x [0, S] of an
     * adipose layer to physical coordinates: x and y are kept, s runs from
     * the bottom of the layer (s = 0) to its top (s = S).
     */
    class LayerReferenceMap
    {
    public:
      LayerReferenceMap(const LayerStack  &layers,
                        const unsigned int layer,
                        const double       height)
        : layers(layers)
        , layer(layer)
        , height(height)
      {
        affine = true;
        for (unsigned int l = 0; l <= layer; ++l)
          affine = affine && layers.layer(l).has_constant_thickness();
      }

      Point<3>
      operator()(const Point<3> &r) const
      {
        const double bottom = layers.depth_of_interface(layer + 1, r[0], r[1]);
        const double t      = layers.layer(layer).thickness(r[0], r[1]);
        return Point<3>(r[0], r[1], -bottom + r[2] / height * t);
      }

      /// Volume ratio dV_physical / dV_reference = t(x, y) / S.
      double
      jacobian(const Point<3> &r) const
      {
        return layers.layer(layer).thickness(r[0], r[1]) / height;
      }

      /// Whether the map is affine (every layer down to this one has a
      /// constant thickness).
      bool affine;

    private:
      const LayerStack  &layers;
      const unsigned int layer;
      const double       height;
    };


    /// Physical volume and centroid of a reference cell: 4-point (degree 2)
    /// quadrature on the fan of tetrahedra from the reference centroid.
    std::pair<double, Point<3>>
    physical_volume_and_centroid(const VoronoiCell       &cell,
                                 const LayerReferenceMap &map)
    {
      if (map.affine)
        return {cell.volume * map.jacobian(cell.centroid), map(cell.centroid)};
      const double a = 0.5854101966249685, b = 0.1381966011250105;
      const double barycentric[4][4] = {{a, b, b, b},
                                        {b, a, b, b},
                                        {b, b, a, b},
                                        {b, b, b, a}};
      double       volume            = 0;
      Point<3>     moment;
      for (const auto &face : cell.faces)
        for (unsigned int k = 1; k + 1 < face.vertices.size(); ++k)
          {
            const std::array<Point<3>, 4> corners = {{cell.centroid,
                                                      face.vertices[0],
                                                      face.vertices[k],
                                                      face.vertices[k + 1]}};
            const double                  reference_volume =
              std::abs((corners[1] - corners[0]) *
                       cross_product_3d(corners[2] - corners[0],
                                        corners[3] - corners[0])) /
              6.;
            for (const auto &weights : barycentric)
              {
                Point<3> r;
                for (unsigned int c = 0; c < 4; ++c)
                  r += weights[c] * corners[c];
                const double dv = reference_volume / 4. * map.jacobian(r);
                volume += dv;
                moment += dv * map(r);
              }
          }
      return {volume, moment / volume};
    }


    /// The wall polygon, fan-triangulated from its vertex average and
    /// subdivided until no edge is longer than @p size, in physical
    /// coordinates.
    std::vector<std::array<Point<3>, 3>>
    triangulate_wall(const std::vector<Point<3>> &polygon,
                     const LayerReferenceMap     &map,
                     const double                 size)
    {
      Point<3> centre;
      for (const auto &p : polygon)
        centre += p / static_cast<double>(polygon.size());
      std::vector<std::array<Point<3>, 3>> triangles;
      for (unsigned int k = 0; k < polygon.size(); ++k)
        {
          const Point<3> &A = centre, &B = polygon[k],
                         &C          = polygon[(k + 1) % polygon.size()];
          const double       longest = std::max({map(A).distance(map(B)),
                                                 map(B).distance(map(C)),
                                                 map(C).distance(map(A))});
          const unsigned int n =
            std::max(1., std::ceil(longest / size - 1e-12));
          const auto point = [&](const unsigned int i, const unsigned int j) {
            return map(A + (double(i) / n) * (B - A) +
                       (double(j) / n) * (C - A));
          };
          for (unsigned int i = 0; i < n; ++i)
            for (unsigned int j = 0; i + j < n; ++j)
              {
                triangles.push_back(
                  {{point(i, j), point(i + 1, j), point(i, j + 1)}});
                if (i + j + 1 < n)
                  triangles.push_back(
                    {{point(i + 1, j), point(i + 1, j + 1), point(i, j + 1)}});
              }
        }
      return triangles;
    }


    double
    triangle_area(const std::array<Point<3>, 3> &t)
    {
      return 0.5 * cross_product_3d(t[1] - t[0], t[2] - t[0]).norm();
    }
  } // namespace


  double
  layer_volume(const LayerStack     &layers,
               const unsigned int    layer,
               const BoundingBox<2> &rectangle)
  {
    const Point<2>    &lo = rectangle.get_boundary_points().first;
    const Point<2>    &hi = rectangle.get_boundary_points().second;
    const unsigned int n  = 16;
    const QGauss<2>    gauss(4);
    const double       hx = (hi[0] - lo[0]) / n, hy = (hi[1] - lo[1]) / n;
    double             volume = 0;
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = 0; j < n; ++j)
        for (unsigned int q = 0; q < gauss.size(); ++q)
          {
            const double x = lo[0] + (i + gauss.point(q)[0]) * hx;
            const double y = lo[1] + (j + gauss.point(q)[1]) * hy;
            volume +=
              gauss.weight(q) * hx * hy * layers.layer(layer).thickness(x, y);
          }
    return volume;
  }


  LayerLobules
  build_layer_lobules(
    const LayerStack                               &layers,
    const unsigned int                              layer,
    const BoundingBox<2>                           &rectangle,
    const MicrostructureParameters                 &parameters,
    const unsigned int                              first_id,
    const std::function<void(const std::string &)> &progress,
    const std::function<void(const std::string &)> &timed_progress)
  {
    Timer        timer;
    const Layer &data = layers.layer(layer);
    AssertThrow(data.is_adipose() && data.lobule_diameter > 0,
                ExcMessage("Layer '" + data.name +
                           "' carries no lobules (needs kind SAT or DAT and "
                           "a positive Lobule diameter)."));
    LayerLobules result;
    result.layer         = layer;
    result.region_volume = layer_volume(layers, layer, rectangle);

    const Point<2> &lo    = rectangle.get_boundary_points().first;
    const Point<2> &hi    = rectangle.get_boundary_points().second;
    const double    area  = (hi[0] - lo[0]) * (hi[1] - lo[1]);
    const double    d     = data.lobule_diameter;
    const double    S     = result.region_volume / area / data.lobule_stretch;
    const double    ball  = M_PI * d * d * d / 6.;
    const double    count = std::round(result.region_volume / ball);
    AssertThrow(count < 2e6,
                ExcMessage("Layer stack/" + data.name +
                           "/Lobule diameter = " + std::to_string(d) +
                           " mm asks for more than 2e6 lobules; use a larger "
                           "diameter or a smaller region of interest."));
    const unsigned int n = std::max(1., count);

    const BoundingBox<3> box(
      std::make_pair(Point<3>(lo[0], lo[1], 0.), Point<3>(hi[0], hi[1], S)));
    std::seed_seq seed_sequence{parameters.seed, layer};
    std::mt19937  generator(seed_sequence);
    std::uniform_real_distribution<double> uniform(0., 1.);
    std::vector<Point<3>>                  seeds(n);
    for (auto &p : seeds)
      for (unsigned int c = 0; c < 3; ++c)
        p[c] = box.get_boundary_points().first[c] +
               uniform(generator) * box.side_length(c);

    if (progress)
      {
        std::ostringstream line;
        line << "Lobules of layer '" << data.name << "': " << n
             << " seeds (d = " << d << " mm), " << parameters.lloyd_iterations
             << " Lloyd iterations";
        progress(line.str());
      }
    // a long relaxation reports every iteration once it has run a while
    result.cvt_energy = lloyd_relaxation(
      box, seeds, parameters.lloyd_iterations, [&](const unsigned int done) {
        if (timed_progress && timer.wall_time() > 5.)
          timed_progress(
            "  Lloyd iteration " + std::to_string(done) + " of " +
            std::to_string(parameters.lloyd_iterations) + " after " +
            std::to_string(static_cast<int>(timer.wall_time())) + " s");
      });
    const std::vector<VoronoiCell> cells =
      compute_clipped_voronoi(box, seeds, true, result.diagnostics);

    result.sites = seeds;
    result.site_lobule =
      std::vector<unsigned int>(n, numbers::invalid_unsigned_int);
    result.reference_height = S;
    const LayerReferenceMap   map(layers, layer, S);
    std::vector<unsigned int> id(n, numbers::invalid_unsigned_int);
    unsigned int              next_id = first_id;
    for (unsigned int i = 0; i < n; ++i)
      {
        const auto [volume, centroid] =
          physical_volume_and_centroid(cells[i], map);
        if (!parameters.region.contains(centroid[0], centroid[1]))
          continue;
        id[i]                 = next_id++;
        result.site_lobule[i] = result.lobules.size();
        result.lobules.push_back(
          {id[i],
           layer,
           centroid,
           volume,
           static_cast<unsigned int>(cells[i].faces.size())});
      }

    const double minimum_area = parameters.minimum_septum_area * d * d;
    for (unsigned int i = 0; i < n; ++i)
      for (const auto &face : cells[i].faces)
        {
          const int j = face.neighbour;
          if (j <= static_cast<int>(i) ||
              id[i] == numbers::invalid_unsigned_int ||
              id[j] == numbers::invalid_unsigned_int)
            continue;
          Septum septum;
          septum.layer     = layer;
          septum.lobules   = {{id[i], id[j]}};
          septum.triangles = triangulate_wall(face.vertices,
                                              map,
                                              parameters.septum_triangle_size);
          septum.area      = 0;
          for (const auto &t : septum.triangles)
            septum.area += triangle_area(t);
          if (septum.area < minimum_area)
            {
              ++result.n_dropped_septa;
              result.dropped_septa_area += septum.area;
              continue;
            }
          result.septa.push_back(std::move(septum));
        }
    result.wall_time = timer.wall_time();
    return result;
  }
} // namespace ssc
