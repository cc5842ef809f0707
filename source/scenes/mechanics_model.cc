#include <ssc/scenes/mechanics_model.h>

namespace ssc
{
  MechanicsModel::MechanicsModel(const Parameters &parameters, SceneRun &scene)
  {
    TimerOutput        &timer = scene.timer();
    ConditionalOStream &pcout = scene.pcout();
    background_mesh = std::make_unique<BackgroundMesh>(parameters.layers,
                                                       parameters.mesh,
                                                       scene.communicator());
    {
      TimerOutput::Scope t(timer, "mesh");
      background_mesh->build();
    }
    pcout << "Mesh: "
          << background_mesh->triangulation().n_global_active_cells()
          << " hexahedra over " << parameters.layers.n_layers() << " layers"
          << std::endl;

    elastic_system = std::make_unique<ElasticSystem>(*background_mesh,
                                                     parameters.layers,
                                                     parameters.elasticity,
                                                     timer);
    {
      TimerOutput::Scope t(timer, "setup");
      elastic_system->field().distribute_dofs();
    }
    pcout << "Degrees of freedom: "
          << elastic_system->field().dof_handler().n_dofs() << " (Q"
          << parameters.elasticity.degree << ", "
          << to_string(parameters.elasticity.formulation) << " formulation)"
          << std::endl;

    microstructure_coupling =
      std::make_unique<MicrostructureCoupling>(parameters.layers,
                                               parameters.mesh,
                                               parameters.microstructure,
                                               parameters.embedded,
                                               *elastic_system,
                                               timer,
                                               pcout);
    microstructure_coupling->setup();
  }
} // namespace ssc
