#include <ssc/mechanics/microstructure_coupling.h>

namespace ssc
{
  MicrostructureCoupling::MicrostructureCoupling(
    const LayerStack               &layers,
    const MeshParameters           &mesh,
    const MicrostructureParameters &microstructure,
    const EmbeddedParameters       &embedded,
    ElasticSystem                  &system,
    TimerOutput                    &timer,
    ConditionalOStream             &pcout)
    : layers(layers)
    , mesh_parameters(mesh)
    , parameters(microstructure)
    , embedded(embedded)
    , septum(IsotropicModuli(embedded.septum_youngs_modulus,
                             embedded.septum_poisson_ratio),
             embedded.septum_thickness,
             embedded.septum_tension_field)
    , ligament(embedded.ligament_youngs_modulus,
               embedded.ligament_area(),
               embedded.ligament_tension_only,
               1. - embedded.ligament_contraction)
    , system(system)
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


  template <int dim, typename Law>
  std::unique_ptr<EmbeddedStiffness>
  MicrostructureCoupling::embed(const Triangulation<dim, 3> &mesh,
                                const Law                   &law,
                                const unsigned int           n_points,
                                double                      &covered,
                                double                      &total)
  {
    if (mesh.n_active_cells() == 0)
      return nullptr;
    Timer      clip_timer;
    const auto quadrature =
      clipped_quadrature(mesh, *locator, n_points, covered);
    clip_seconds += clip_timer.wall_time();
    total = measure(mesh);
    auto stiffness =
      std::make_unique<EmbeddedStiffness>(quadrature,
                                          law,
                                          system.field().fe(),
                                          system.field().mapping(),
                                          locator->communicator());
    system.attach(*stiffness);
    return stiffness;
  }


  void
  MicrostructureCoupling::setup(ConditionalOStream *timed_progress)
  {
    if (!parameters.lobules && !parameters.ligaments)
      return;
    {
      TimerOutput::Scope t(timer, "microstructure");
      microstructure =
        std::make_unique<Microstructure>(layers,
                                         mesh_parameters.patch_length_x,
                                         mesh_parameters.patch_length_y,
                                         parameters);
      const auto print_on = [](ConditionalOStream *stream) {
        return
          [stream](const std::string &line) { *stream << line << std::endl; };
      };
      microstructure->build(print_on(&pcout),
                            timed_progress != nullptr ?
                              print_on(timed_progress) :
                              std::function<void(const std::string &)>());
    }

    TimerOutput::Scope t(timer, "embedding");
    locator = std::make_unique<PointLocator>(system.field().triangulation(),
                                             system.field().mapping());
    if (embedded.septa_stiffness)
      septa = embed(microstructure->septa_mesh(),
                    septum,
                    embedded.septum_quadrature,
                    septa_area_covered,
                    septa_area);
    if (embedded.ligament_stiffness)
      cables = embed(microstructure->ligament_mesh(),
                     ligament,
                     embedded.ligament_quadrature,
                     ligament_length_covered,
                     ligament_length);
    pcout << "Embedded: " << (septa ? septa->n_points() : 0)
          << " septa quadrature points (" << septa_area_covered << " of "
          << septa_area << " mm^2), " << (cables ? cables->n_points() : 0)
          << " ligament quadrature points (" << ligament_length_covered
          << " of " << ligament_length << " mm)" << std::endl;
  }


  void
  MicrostructureCoupling::grow_septa(
    const GrowthField                         &growth,
    const std::function<double(unsigned int)> &weight,
    const double                               follow)
  {
    if (!septa || follow == 0)
      return;
    septum_growth_weight = weight;
    septa->grow_with(growth, weight, follow);
  }


  double
  MicrostructureCoupling::septum_growth_stretch_square(
    const unsigned int septum) const
  {
    return septum_growth_weight ?
             septa->growth_stretch_square(septum_growth_weight(septum)) :
             1.;
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
