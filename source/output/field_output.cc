#include <deal.II/base/utilities.h>

#include <functional>

#include <ssc/output/field_output.h>
#include <ssc/output/volume_output.h>

namespace ssc
{
  FieldOutput::FieldOutput(ElasticSystem                &system,
                           const MicrostructureCoupling &coupling,
                           const Kinematics              kinematics)
    : field(system.field())
    , materials(system.materials())
    , growth(system.growth())
    , history(system.history())
    , coupling(coupling)
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


  namespace
  {
    /// Writes <family>_<step>.vtu with @p writer: the measure @p name of
    /// the structure's law and the structure's id (@p id_name), and records
    /// it in <family>.pvd.
    template <int dim>
    void
    write_family(const EmbeddedFieldWriter<dim>                  &writer,
                 const std::string                               &family,
                 const std::string                               &name,
                 const std::function<double(const Tensor<2, 3> &,
                                            const Tensor<1, 3> &,
                                            types::material_id)> &measure,
                 const std::string                               &id_name,
                 const DisplacementField                         &field,
                 RunOutput                                       &output,
                 const unsigned int                               step,
                 const double                                     time)
    {
      const std::string file =
        family + "_" + Utilities::int_to_string(step, 4) + ".vtu";
      writer.write(output,
                   file,
                   field,
                   {{name,
                     [&](const Tensor<2, 3>      &F,
                         const Tensor<1, 3>      &direction,
                         const types::material_id material) {
                       return measure(F, direction, material);
                     }},
                    {id_name,
                     [](const Tensor<2, 3> &,
                        const Tensor<1, 3> &,
                        const types::material_id material) {
                       return double(material);
                     }}});
      output.add_pvd_record(family, time, file);
    }
  } // namespace


  void
  FieldOutput::write(RunOutput         &output,
                     const unsigned int step,
                     const double       time) const
  {
    output.add_pvd_record(
      "volume",
      time,
      write_volume_vtu(field, materials, growth, history, output, step));
    if (septa_writer)
      write_family<2>(
        *septa_writer,
        "septa",
        "membrane_stress_von_mises",
        [this](const Tensor<2, 3>      &F,
               const Tensor<1, 3>      &normal,
               const types::material_id septum) {
          // a grown septum's elastic part: F / lambda_g in its plane
          const double stretch =
            std::sqrt(coupling.septum_growth_stretch_square(septum));
          return coupling.septum_law().von_mises_stress(F / stretch,
                                                        normal,
                                                        kinematics);
        },
        "septum",
        field,
        output,
        step,
        time);
    if (ligament_writer)
      write_family<1>(
        *ligament_writer,
        "ligaments",
        "axial_force_N",
        [this](const Tensor<2, 3> &F,
               const Tensor<1, 3> &tangent,
               types::material_id) {
          return coupling.ligament_law().current_force(F, tangent, kinematics);
        },
        "ligament",
        field,
        output,
        step,
        time);
  }
} // namespace ssc
