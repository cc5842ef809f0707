#include <deal.II/base/utilities.h>

#include <ssc/output/microstructure_output.h>

namespace ssc
{
  MicrostructureOutput::MicrostructureOutput(
    const MicrostructureCoupling &coupling,
    const Kinematics              kinematics)
    : coupling(coupling)
    , kinematics(kinematics)
  {
    const Microstructure *microstructure = coupling.get_microstructure();
    if (coupling.septa_coupled())
      septa_writer =
        std::make_unique<EmbeddedFieldWriter<2>>(microstructure->septa_mesh(),
                                                 *coupling.get_locator());
    if (coupling.ligaments_coupled())
      ligament_writer = std::make_unique<EmbeddedFieldWriter<1>>(
        microstructure->ligament_mesh(), *coupling.get_locator());
  }


  void
  MicrostructureOutput::write(const DisplacementField &field,
                              RunOutput               &output,
                              const unsigned int       step,
                              const double             time) const
  {
    const auto id = [](const Tensor<2, 3> &,
                       const Tensor<1, 3> &,
                       const types::material_id material) {
      return double(material);
    };
    if (septa_writer)
      {
        const MembraneLaw &law = coupling.septum_law();
        const std::string  file =
          "septa_" + Utilities::int_to_string(step, 4) + ".vtu";
        septa_writer->write(output.path(file),
                            field,
                            {{"membrane_stress_von_mises",
                              [&](const Tensor<2, 3> &F,
                                  const Tensor<1, 3> &normal,
                                  types::material_id) {
                                return law.von_mises_stress(F,
                                                            normal,
                                                            kinematics);
                              }},
                             {"septum", id}});
        output.add_pvd_record("septa", time, file);
      }
    if (ligament_writer)
      {
        const CableLaw   &law = coupling.ligament_law();
        const std::string file =
          "ligaments_" + Utilities::int_to_string(step, 4) + ".vtu";
        ligament_writer->write(output.path(file),
                               field,
                               {{"axial_force_N",
                                 [&](const Tensor<2, 3> &F,
                                     const Tensor<1, 3> &tangent,
                                     types::material_id) {
                                   return law.current_force(F,
                                                            tangent,
                                                            kinematics);
                                 }},
                                {"ligament", id}});
        output.add_pvd_record("ligaments", time, file);
      }
  }
} // namespace ssc
