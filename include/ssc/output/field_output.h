#ifndef ssc_output_field_output_h
#define ssc_output_field_output_h

#include <memory>

#include <ssc/mechanics/displacement_field.h>
#include <ssc/mechanics/elastic_system.h>
#include <ssc/mechanics/microstructure_coupling.h>
#include <ssc/output/embedded_output.h>
#include <ssc/output/run_output.h>

namespace ssc
{
  /**
   * Writes the fields of a scene, step by step: the volume (displacement
   * and each layer's own stress, write_volume_vtu()) and the coupled septa
   * and ligaments with the background displacement interpolated, the
   * septa's membrane von Mises stress and the ligaments' axial force from
   * their own laws (finite strain where the problem is, small strain
   * otherwise), and their ids; volume.pvd, septa.pvd and ligaments.pvd
   * record the steps.
   */
  class FieldOutput
  {
  public:
    /// The fields of @p system with the microstructure of @p coupling;
    /// @p kinematics: how the embedded stresses are measured.
    FieldOutput(ElasticSystem                &system,
                const MicrostructureCoupling &coupling,
                const Kinematics              kinematics);

    /// Writes volume_<step>, septa_<step> and ligaments_<step> with their
    /// PVD records at @p time (collective).
    void
    write(RunOutput &output, const unsigned int step, const double time) const;

  private:
    const DisplacementField                &field;
    const LayerMaterials                   &materials;
    const GrowthField                      &growth;
    const QuadratureHistory                &history;
    const MicrostructureCoupling           &coupling;
    const Kinematics                        kinematics;
    std::unique_ptr<EmbeddedFieldWriter<2>> septa_writer;
    std::unique_ptr<EmbeddedFieldWriter<1>> ligament_writer;
  };
} // namespace ssc

#endif
