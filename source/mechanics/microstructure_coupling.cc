#include <ssc/mechanics/microstructure_coupling.h>

namespace ssc
{
  MicrostructureCoupling::MicrostructureCoupling(const Parameters   &parameters,
                                                 BackgroundMesh     &mesh,
                                                 VolumeElasticity   &elasticity,
                                                 TimerOutput        &timer,
                                                 ConditionalOStream &pcout)
    : parameters(parameters)
    , septum_material{parameters.embedded.septum_youngs_modulus,
                      parameters.embedded.septum_poisson_ratio,
                      parameters.embedded.septum_thickness}
    , ligament_material{parameters.embedded.ligament_youngs_modulus,
                        0.,
                        parameters.embedded.ligament_area()}
    , mesh(mesh)
    , elasticity(elasticity)
    , timer(timer)
    , pcout(pcout)
  {}


  namespace
  {
    /// Total area (triangles) or length (segments) of an embedded mesh.
    template <int dim>
    double
    measure(const Triangulation<dim, 3> &mesh)
    {
      double sum = 0;
      for (const auto &cell : mesh.active_cell_iterators())
        sum += cell->measure();
      return sum;
    }
  } // namespace


  template <int dim>
  std::unique_ptr<EmbeddedElasticity>
  MicrostructureCoupling::embed(const Triangulation<dim, 3> &mesh,
                                const EmbeddedKind           kind,
                                const EmbeddedMaterial      &material,
                                const unsigned int           n_points,
                                double                      &covered,
                                double                      &total)
  {
    Timer      clip_timer;
    const auto quadrature =
      clipped_quadrature(mesh, *locator, n_points, covered);
    clip_seconds += clip_timer.wall_time();
    total          = measure(mesh);
    auto stiffness = std::make_unique<EmbeddedElasticity>(
      kind,
      quadrature,
      [material](types::material_id) { return material; },
      elasticity.get_fe(),
      elasticity.get_mapping(),
      locator->communicator(),
      kind == EmbeddedKind::cable ? parameters.embedded.ligament_tension_only :
                                    parameters.embedded.septum_tension_field);
    elasticity.attach(*stiffness);
    return stiffness;
  }


  void
  MicrostructureCoupling::setup()
  {
    const MicrostructureParameters &m = parameters.microstructure;
    const EmbeddedParameters       &e = parameters.embedded;
    if (!m.lobules && !m.ligaments)
      return;
    {
      TimerOutput::Scope t(timer, "microstructure");
      microstructure =
        std::make_unique<Microstructure>(parameters.layers,
                                         parameters.mesh.patch_length_x,
                                         parameters.mesh.patch_length_y,
                                         m);
      microstructure->build(
        [this](const std::string &line) { pcout << line << std::endl; });
    }

    TimerOutput::Scope t(timer, "embedding");
    locator = std::make_unique<PointLocator>(mesh.triangulation(),
                                             elasticity.get_mapping());
    if (e.septa_stiffness && microstructure->septa_mesh().n_active_cells() > 0)
      {
        septa = embed(microstructure->septa_mesh(),
                      EmbeddedKind::membrane,
                      septum_material,
                      e.septum_quadrature,
                      septa_area_covered,
                      septa_area);
        septa_writer =
          std::make_unique<EmbeddedFieldWriter<2>>(microstructure->septa_mesh(),
                                                   *locator);
      }
    if (e.ligament_stiffness &&
        microstructure->ligament_mesh().n_active_cells() > 0)
      {
        cables          = embed(microstructure->ligament_mesh(),
                       EmbeddedKind::cable,
                       ligament_material,
                       e.ligament_quadrature,
                       ligament_length_covered,
                       ligament_length);
        ligament_writer = std::make_unique<EmbeddedFieldWriter<1>>(
          microstructure->ligament_mesh(), *locator);
      }
    pcout << "Embedded: " << (septa ? septa->n_points() : 0)
          << " septa quadrature points (" << septa_area_covered << " of "
          << septa_area << " mm^2), " << (cables ? cables->n_points() : 0)
          << " ligament quadrature points (" << ligament_length_covered
          << " of " << ligament_length << " mm)" << std::endl;
  }


  void
  MicrostructureCoupling::write(RunOutput         &output,
                                const unsigned int step,
                                const double       time) const
  {
    if (septa)
      {
        const EmbeddedMaterial &material = septum_material;
        const std::string       file =
          "septa_" + Utilities::int_to_string(step, 4) + ".vtu";
        septa_writer->write(
          output.path(file),
          elasticity,
          {{"membrane_stress_von_mises",
            [&](const SymmetricTensor<2, 3> &eps,
                const Tensor<1, 3>          &normal,
                types::material_id) {
              return septa->axial_or_membrane_stress(eps, normal, material);
            }},
           {"septum",
            [](const SymmetricTensor<2, 3> &,
               const Tensor<1, 3> &,
               const types::material_id id) { return double(id); }}});
        output.add_pvd_record("septa", time, file);
      }
    if (cables)
      {
        const EmbeddedMaterial &material = ligament_material;
        const std::string       file =
          "ligaments_" + Utilities::int_to_string(step, 4) + ".vtu";
        ligament_writer->write(
          output.path(file),
          elasticity,
          {{"axial_force_N",
            [&](const SymmetricTensor<2, 3> &eps,
                const Tensor<1, 3>          &tangent,
                types::material_id) {
              return material.size *
                     cables->axial_or_membrane_stress(eps, tangent, material);
            }},
           {"ligament",
            [](const SymmetricTensor<2, 3> &,
               const Tensor<1, 3> &,
               const types::material_id id) { return double(id); }}});
        output.add_pvd_record("ligaments", time, file);
      }
  }


  nlohmann::ordered_json
  MicrostructureCoupling::embedded_summary() const
  {
    nlohmann::ordered_json summary = {
      {"septa_triangles",
       microstructure ? microstructure->septa_mesh().n_active_cells() : 0},
      {"ligament_segments",
       microstructure ? microstructure->ligament_mesh().n_active_cells() : 0},
      {"lobules", microstructure ? microstructure->n_lobules() : 0},
      {"septa_coupled", septa != nullptr},
      {"ligaments_coupled", cables != nullptr},
      {"septa_quadrature_points", septa ? septa->n_points() : 0},
      {"ligament_quadrature_points", cables ? cables->n_points() : 0},
      {"septa_area_mm2", septa_area},
      {"septa_area_in_quadrature_mm2", septa_area_covered},
      {"ligament_length_mm", ligament_length},
      {"ligament_length_in_quadrature_mm", ligament_length_covered},
      {"clip_seconds", clip_seconds}};
    if (microstructure)
      summary["fasciotomy"] = microstructure->fasciotomy_summary();
    return summary;
  }
} // namespace ssc
