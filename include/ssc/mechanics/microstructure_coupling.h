#ifndef ssc_mechanics_microstructure_coupling_h
#define ssc_mechanics_microstructure_coupling_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>

#include <nlohmann/json.hpp>

#include <memory>

#include <ssc/embedding/point_locator.h>
#include <ssc/materials/cable_law.h>
#include <ssc/materials/membrane_law.h>
#include <ssc/mechanics/elastic_system.h>
#include <ssc/mechanics/embedded_parameters.h>
#include <ssc/mechanics/embedded_stiffness.h>
#include <ssc/microstructure/microstructure.h>
#include <ssc/microstructure/microstructure_parameters.h>

namespace ssc
{
  /**
   * The hybrid model's microstructure in a mechanics scene: builds the
   * lobules, septa and ligaments the parameters ask for, embeds the septa as
   * membranes and the ligaments as cables in the background mesh (each can
   * be switched off in the section "Embedded") and attaches their
   * stiffness to the elastic system. output/microstructure_output.h writes
   * them.
   */
  class MicrostructureCoupling
  {
  public:
    MicrostructureCoupling(const LayerStack               &layers,
                           const MeshParameters           &mesh,
                           const MicrostructureParameters &microstructure,
                           const EmbeddedParameters       &embedded,
                           ElasticSystem                  &system,
                           TimerOutput                    &timer,
                           ConditionalOStream             &pcout);

    /// Builds and embeds (timed as "microstructure" and "embedding").
    void
    setup(ConditionalOStream *timed_progress = nullptr);

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

    /// The locator of the background mesh (null while nothing is built).
    const PointLocator *
    get_locator() const
    {
      return locator.get();
    }

    /// Whether the septa and the ligaments are coupled.
    bool
    septa_coupled() const
    {
      return septa != nullptr;
    }

    bool
    ligaments_coupled() const
    {
      return cables != nullptr;
    }

    /**
     * Lets the septa grow with the fat (EmbeddedStiffness::grow_with()) by
     * the growth weight @p weight(septum) of each septum (an index into
     * Microstructure::septa()): @p follow = 1 grows them as a line of the
     * fat grows, 0 not at all. Nothing happens without coupled septa.
     */
    void
    grow_septa(const GrowthField                         &growth,
               const std::function<double(unsigned int)> &weight,
               const double                               follow);

    /// The in-plane growth stretch squared of the septum @p septum now (1
    /// when the septa do not grow).
    double
    septum_growth_stretch_square(const unsigned int septum) const;

    const MembraneLaw &
    septum_law() const
    {
      return septum;
    }

    const CableLaw &
    ligament_law() const
    {
      return ligament;
    }

  private:
    /// Splits @p mesh along the background cells into the quadrature of
    /// @p n_points per direction, attaches the stiffness of @p law there to
    /// the system and returns it (null for an empty mesh); @p covered and
    /// @p total are the measure in the quadrature and of the mesh.
    template <int dim, typename Law>
    std::unique_ptr<EmbeddedStiffness>
    embed(const Triangulation<dim, 3> &mesh,
          const Law                   &law,
          const unsigned int           n_points,
          double                      &covered,
          double                      &total);

    const LayerStack                  &layers;
    const MeshParameters              &mesh_parameters;
    const MicrostructureParameters    &parameters;
    const EmbeddedParameters          &embedded;
    const MembraneLaw                  septum;
    const CableLaw                     ligament;
    ElasticSystem                     &system;
    TimerOutput                       &timer;
    ConditionalOStream                &pcout;
    std::unique_ptr<Microstructure>    microstructure;
    std::unique_ptr<PointLocator>      locator;
    std::unique_ptr<EmbeddedStiffness> septa, cables;
    /// The growth weight of each septum (empty: the septa do not grow).
    std::function<double(unsigned int)> septum_growth_weight;
    /// Wall time to split septa and ligaments along the background cells.
    double clip_seconds = 0;
    /// Area of septa and length of ligaments in the quadrature, and their
    /// totals in the embedded meshes.
    double septa_area = 0, septa_area_covered = 0;
    double ligament_length = 0, ligament_length_covered = 0;
  };
} // namespace ssc

#endif
