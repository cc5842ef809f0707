#include <deal.II/base/bounding_box.h>

#include <cmath>
#include <sstream>

#include <ssc/mesh/background_mesh.h>
#include <ssc/microstructure/ligaments.h>
#include <ssc/microstructure/lobules.h>
#include <ssc/scenes/model_size.h>

namespace ssc
{
  double
  bytes_per_dof(const unsigned int degree)
  {
    // 4.3 kB per DoF measured with Q1 (349k DoFs, 1.5 GB); a Q2 row holds
    // about 375 instead of 81 entries of its matrix
    return degree == 1 ? 4.5e3 : 9e3;
  }


  namespace
  {
    /// Lobules of the fat layers over the region of interest and the
    /// septum triangles they will be meshed with.
    void
    check_lobules(const Parameters &parameters, const BoundingBox<2> &region)
    {
      const ResourceLimits &limits = parameters.limits;
      const double          h = parameters.microstructure.septum_triangle_size;
      double                lobules = 0, triangles = 0, largest = 0;
      std::string           densest;
      for (unsigned int l = 0; l < parameters.layers.n_layers(); ++l)
        {
          const Layer &layer = parameters.layers.layer(l);
          if (!layer.is_adipose() || layer.lobule_diameter <= 0)
            continue;
          const double d    = layer.lobule_diameter;
          const double ball = M_PI * d * d * d / 6.;
          const double n =
            std::max(1., layer_volume(parameters.layers, l, region) / ball);
          lobules += n;
          if (n > largest)
            {
              largest = n;
              densest = layer.name;
            }
          // a lobule's walls: half the surface of its Voronoi cell (about
          // 5.3 V^{2/3}), each wall at least a few triangles
          const double wall_area = 0.5 * 5.3 * std::pow(ball, 2. / 3.);
          triangles +=
            n * std::max(30., wall_area / (0.25 * std::sqrt(3.) * h * h));
        }
      ResourceLimits::require(lobules,
                              limits.max_lobules,
                              "The number of lobules (most in layer '" +
                                densest + "')",
                              "Max lobules",
                              "use a larger Layer stack/" + densest +
                                "/Lobule diameter or a smaller "
                                "Microstructure/Region of interest");
      ResourceLimits::require(triangles,
                              limits.max_septum_triangles,
                              "The number of septum triangles",
                              "Max septum triangles",
                              "use a larger Microstructure/Septum triangle "
                              "size");
    }


    /// Ligaments times their segments, the length bounded by the depth of
    /// the deepest layer's top at the patch centre.
    void
    check_ligaments(const Parameters &parameters, const BoundingBox<2> &region)
    {
      const LigamentDensity density(region, parameters.microstructure);
      const LayerStack     &layers = parameters.layers;
      const double          length =
        layers.depth_of_interface(layers.n_layers() - 1, 0., 0.);
      const double segments =
        std::ceil(length / parameters.microstructure.ligament_segment_length);
      std::ostringstream what;
      what.precision(3);
      what << "The number of ligament segments (" << density.expected
           << " ligaments of up to " << segments << " segments)";
      ResourceLimits::require(density.expected * segments,
                              parameters.limits.max_ligament_segments,
                              what.str(),
                              "Max ligament segments",
                              "lower Microstructure/Ligaments/Density, use a "
                              "larger Segment length or a smaller "
                              "Microstructure/Region of interest");
    }
  } // namespace


  void
  check_model_size(const Parameters &parameters)
  {
    const ResourceLimits &limits = parameters.limits;
    const double          cells =
      BackgroundMesh::estimated_cells(parameters.layers, parameters.mesh);
    const std::string coarser = parameters.mesh.coarsening_advice();
    ResourceLimits::require(cells,
                            limits.max_cells,
                            "The background mesh's cell count",
                            "Max cells",
                            coarser);
    if (parameters.run.scene != SceneKind::geometry)
      {
        const unsigned int degree = parameters.elasticity.degree;
        const double       dofs   = 3. * cells * std::pow(degree, 3);
        ResourceLimits::require(
          dofs, limits.max_dofs, "The number of DoFs", "Max DoFs", coarser);
        limits.require_memory(dofs * bytes_per_dof(degree),
                              "The linear system (" +
                                std::to_string(static_cast<long>(dofs)) +
                                " DoFs, estimated)",
                              coarser + ", or lower Elasticity/Degree");
      }
    if (parameters.microstructure.lobules ||
        parameters.microstructure.ligaments)
      {
        const BoundingBox<2> region =
          parameters.microstructure.region.bounding_rectangle(
            parameters.mesh.patch_length_x, parameters.mesh.patch_length_y);
        if (parameters.microstructure.lobules)
          check_lobules(parameters, region);
        if (parameters.microstructure.ligaments)
          check_ligaments(parameters, region);
      }
    if (parameters.run.scene == SceneKind::growth)
      {
        const double spacing = parameters.growth.grid_spacing;
        ResourceLimits::require((parameters.mesh.patch_length_x / spacing + 1) *
                                  (parameters.mesh.patch_length_y / spacing +
                                   1),
                                limits.max_grid_points,
                                "The number of skin-elevation grid points",
                                "Max grid points",
                                "use a larger Growth/Grid spacing");
      }
  }
} // namespace ssc
