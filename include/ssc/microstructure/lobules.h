#ifndef ssc_microstructure_lobules_h
#define ssc_microstructure_lobules_h

#include <deal.II/base/bounding_box.h>
#include <deal.II/base/point.h>

#include <array>
#include <functional>
#include <string>
#include <vector>

#include <ssc/mesh/layer_stack.h>
#include <ssc/microstructure/clipped_voronoi.h>
#include <ssc/microstructure/microstructure_parameters.h>

namespace ssc
{
  /// One fat lobule: a clipped Voronoi cell of an adipose layer, mapped to
  /// physical coordinates.
  struct Lobule
  {
    unsigned int id;
    unsigned int layer;
    Point<3>     centroid;
    double       volume; ///< mm^3
    /// Faces of the cell (walls to other lobules and sides of the layer).
    unsigned int n_faces;
  };

  /// A septum: the wall between two lobules of one layer, as a flat-faceted
  /// surface in physical coordinates.
  struct Septum
  {
    unsigned int                         layer;
    std::array<unsigned int, 2>          lobules;
    std::vector<std::array<Point<3>, 3>> triangles;
    double                               area; ///< mm^2
  };

  /// The lobules and septa of one adipose layer and how they were made.
  struct LayerLobules
  {
    unsigned int        layer = 0;
    std::vector<Lobule> lobules;
    std::vector<Septum> septa;
    /// Volume of the layer over the tessellated rectangle (mm^3).
    double region_volume = 0;
    /// The Voronoi generators after Lloyd, in the layer's reference box
    /// (x, y, s), s in [0, reference_height]: the lobule of a point is the
    /// one of its nearest generator there (LobuleLocator).
    std::vector<Point<3>> sites;
    /// Index into lobules of the cell of each site, or
    /// numbers::invalid_unsigned_int where the lobule was dropped (outside
    /// the region of interest).
    std::vector<unsigned int> site_lobule;
    double                    reference_height = 0;
    /// CVT energy before and after every Lloyd iteration.
    std::vector<double> cvt_energy;
    VoronoiDiagnostics  diagnostics;
    /// Walls dropped as slivers (Microstructure/Minimum septum area).
    unsigned int n_dropped_septa    = 0;
    double       dropped_septa_area = 0;
    double       wall_time          = 0;
  };

  /**
   * Builds the lobules of adipose layer @p layer over the rectangle
   * @p rectangle (the region of interest clipped to the patch).
   *
   * The tessellation lives in the layer's reference box (x, y, s), s in
   * [0, S] with S = (mean thickness) / (vertical stretch): there the lobules
   * are isotropic. The map x = (x, y, -depth_bottom(x, y) + s/S t(x, y))
   * stretches them vertically and follows any thickness map t(x, y), so a
   * variable thickness needs no special case. Seeds are uniform (std::mt19937
   * seeded with the seed and the layer index), relaxed by Lloyd iterations
   * in the reference box; volumes and centroids are integrated over the
   * mapped cells (exact for thickness maps linear in x and y).
   *
   * With a cylindrical region, lobules whose centroid lies outside the
   * cylinder are dropped, with their septa. Lobule ids start at
   * @p first_id. @p progress receives one line on the seeds,
   * @p timed_progress each Lloyd iteration once the relaxation has run for
   * a few seconds.
   */
  LayerLobules
  build_layer_lobules(
    const LayerStack                               &layers,
    const unsigned int                              layer,
    const BoundingBox<2>                           &rectangle,
    const MicrostructureParameters                 &parameters,
    const unsigned int                              first_id,
    const std::function<void(const std::string &)> &progress       = {},
    const std::function<void(const std::string &)> &timed_progress = {});

  /// Volume (mm^3) of layer @p layer over @p rectangle, by Gauss quadrature
  /// of its thickness (exact for polynomial thickness maps up to degree 7).
  double
  layer_volume(const LayerStack     &layers,
               const unsigned int    layer,
               const BoundingBox<2> &rectangle);
} // namespace ssc

#endif
