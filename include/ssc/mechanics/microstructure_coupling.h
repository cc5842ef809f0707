#ifndef ssc_mechanics_microstructure_coupling_h
#define ssc_mechanics_microstructure_coupling_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>

#include <nlohmann/json.hpp>
#include <ssc/embedding/embedded_output.h>
#include <ssc/embedding/point_locator.h>
#include <ssc/mechanics/embedded_elasticity.h>
#include <ssc/mechanics/volume_elasticity.h>
#include <ssc/microstructure/microstructure.h>
#include <ssc/output.h>
#include <ssc/parameters.h>

#include <memory>

namespace ssc
{
  /**
   * The hybrid model's microstructure in a mechanics scene: builds the
   * lobules, septa and ligaments the parameters ask for, embeds the septa as
   * membranes and the ligaments as cables in the background mesh (each can
   * be switched off in the section "Embedded"), attaches their stiffness to
   * the volume elasticity, and writes septa and ligaments with the
   * interpolated displacement, membrane stress and cable force.
   */
  class MicrostructureCoupling
  {
  public:
    MicrostructureCoupling(const Parameters   &parameters,
                           BackgroundMesh     &mesh,
                           VolumeElasticity   &elasticity,
                           TimerOutput        &timer,
                           ConditionalOStream &pcout);

    /// Builds and embeds (timed as "microstructure" and "embedding").
    void
    setup();

    /// Writes septa_<step>.vtu and ligaments_<step>.vtu with PVD records.
    void
    write(RunOutput &output, const unsigned int step, const double time) const;

    /// The summary's "embedded" entry (counts of triangles, segments,
    /// lobules and quadrature points, and what a fasciotomy cut).
    nlohmann::ordered_json
    embedded_summary() const;

    /// The lobules, septa and ligaments (null while the microstructure is
    /// off).
    const Microstructure *
    get_microstructure() const
    {
      return microstructure.get();
    }

    /// Whether anything is embedded.
    bool
    active() const
    {
      return septa != nullptr || cables != nullptr;
    }

  private:
    /// Splits @p mesh along the background cells, attaches its stiffness to
    /// the volume elasticity, and returns it; @p covered and @p total are
    /// the measure in the quadrature and of the mesh.
    template <int dim>
    std::unique_ptr<EmbeddedElasticity>
    embed(const Triangulation<dim, 3> &mesh,
          const EmbeddedKind           kind,
          const EmbeddedMaterial      &material,
          const unsigned int           n_points,
          double                      &covered,
          double                      &total);

    const Parameters      &parameters;
    const EmbeddedMaterial septum_material, ligament_material;
    BackgroundMesh        &mesh;
    VolumeElasticity      &elasticity;
    TimerOutput           &timer;
    ConditionalOStream    &pcout;

    std::unique_ptr<Microstructure>         microstructure;
    std::unique_ptr<PointLocator>           locator;
    std::unique_ptr<EmbeddedElasticity>     septa, cables;
    std::unique_ptr<EmbeddedFieldWriter<2>> septa_writer;
    std::unique_ptr<EmbeddedFieldWriter<1>> ligament_writer;
    /// Wall time to split septa and ligaments along the background cells.
    double clip_seconds = 0;
    /// Area of septa and length of ligaments in the quadrature, and their
    /// totals in the embedded meshes.
    double septa_area = 0, septa_area_covered = 0;
    double ligament_length = 0, ligament_length_covered = 0;
  };
} // namespace ssc

#endif
