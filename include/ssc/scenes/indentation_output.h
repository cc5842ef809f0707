#ifndef ssc_scenes_indentation_output_h
#define ssc_scenes_indentation_output_h

#include <vector>

#include <ssc/embedding/point_locator.h>
#include <ssc/materials/layer_materials.h>
#include <ssc/mechanics/displacement_field.h>
#include <ssc/microstructure/microstructure.h>
#include <ssc/output/run_output.h>
#include <ssc/scenes/parameters.h>
#include <ssc/scenes/quasi_static_driver.h>

namespace ssc
{
  /// The points of the surface profile: y = 0, z = 0, centred in x (or
  /// from x = 0 outwards @p from_centre, for a quarter model).
  std::vector<Point<3>>
  profile_points(const PunchParameters &punch,
                 const double           patch_length,
                 const bool             from_centre);

  /// u_z of @p field at the located points @p locations (collective).
  std::vector<double>
  vertical_displacements(const std::vector<PointLocation> &locations,
                         const DisplacementField          &field);

  /**
   * Each layer's compressive strain under the punch centre, as an
   * ultrasound image on the punch's axis measures it: the change of the
   * layer's thickness over its thickness, from u_z at the layer interfaces
   * on x = y = 0 (located once, evaluated per state).
   */
  class CentreAxisStrains
  {
  public:
    CentreAxisStrains(const LayerStack &stack, const PointLocator &locator);

    /// The strains of the current state of @p field, from the top layer
    /// down (collective).
    std::vector<double>
    evaluate(const DisplacementField &field) const;

  private:
    std::vector<Point<3>>      interfaces;
    std::vector<PointLocation> locations;
  };

  /// Writes surface_profile.csv: x, then u_z per load step.
  void
  write_surface_profile(const PunchParameters                  &punch,
                        const std::vector<Point<3>>            &points,
                        const std::vector<double>              &loads,
                        const std::vector<std::vector<double>> &profiles,
                        RunOutput                              &output);

  /// Writes section.csv: displacement and von Mises stress (from each
  /// layer's own law) on a grid of the plane y = 0 at the current state.
  void
  write_section(const Parameters        &parameters,
                const PointLocator      &locator,
                const DisplacementField &field,
                const LayerMaterials    &materials,
                RunOutput               &output);

  /**
   * Writes section_septa.csv: the septa's traces in the section plane
   * y = 0 (where each septum triangle crosses it, within the section's
   * x range), one segment per row with the displacement of its two ends,
   * so that the section can be drawn in the deformed configuration with
   * the lobule walls in it.
   */
  void
  write_septa_section(const Parameters        &parameters,
                      const Microstructure    &microstructure,
                      const PointLocator      &locator,
                      const DisplacementField &field,
                      RunOutput               &output);

  /// Writes force_displacement.csv: per step force, depth and what the
  /// solvers did.
  void
  write_force_displacement(const std::vector<double>         &forces,
                           const std::vector<double>         &depths,
                           const std::vector<StepStatistics> &statistics,
                           RunOutput                         &output);
} // namespace ssc

#endif
