#ifndef ssc_output_microstructure_output_h
#define ssc_output_microstructure_output_h

#include <memory>

#include <ssc/mechanics/displacement_field.h>
#include <ssc/mechanics/microstructure_coupling.h>
#include <ssc/output/embedded_output.h>
#include <ssc/output/run_output.h>

namespace ssc
{
  /**
   * Writes the coupled septa and ligaments of a scene, step by step, with
   * the background displacement interpolated, the septa's membrane von
   * Mises stress and the ligaments' axial force from their own laws
   * (finite strain where the problem is, small strain otherwise), and
   * their ids; septa.pvd and ligaments.pvd record the steps.
   */
  class MicrostructureOutput
  {
  public:
    /// @p kinematics: how the stresses are measured.
    MicrostructureOutput(const MicrostructureCoupling &coupling,
                         const Kinematics              kinematics);

    /// Writes septa_<step>.vtu and ligaments_<step>.vtu with PVD records.
    void
    write(const DisplacementField &field,
          RunOutput               &output,
          const unsigned int       step,
          const double             time) const;

  private:
    const MicrostructureCoupling           &coupling;
    const Kinematics                        kinematics;
    std::unique_ptr<EmbeddedFieldWriter<2>> septa_writer;
    std::unique_ptr<EmbeddedFieldWriter<1>> ligament_writer;
  };
} // namespace ssc

#endif
