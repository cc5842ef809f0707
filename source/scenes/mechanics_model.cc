#include <ssc/scenes/mechanics_model.h>

namespace ssc
{
  MechanicsModel::MechanicsModel(const Parameters   &parameters,
                                 const MPI_Comm      mpi_communicator,
                                 TimerOutput        &timer,
                                 ConditionalOStream &pcout)
  {
    background_mesh = std::make_unique<BackgroundMesh>(parameters.layers,
                                                       parameters.mesh,
                                                       mpi_communicator);
    {
      TimerOutput::Scope t(timer, "mesh");
      background_mesh->build();
    }
    pcout << "Mesh: "
          << background_mesh->triangulation().n_global_active_cells()
          << " hexahedra over " << parameters.layers.n_layers() << " layers"
          << std::endl;

    volume_elasticity = std::make_unique<VolumeElasticity>(
      *background_mesh, parameters.layers, parameters.elasticity, timer, pcout);
    {
      TimerOutput::Scope t(timer, "setup");
      volume_elasticity->setup_dofs();
    }
    pcout << "Degrees of freedom: " << volume_elasticity->n_dofs() << " (Q"
          << parameters.elasticity.degree << ", "
          << to_string(parameters.elasticity.formulation) << " formulation)"
          << std::endl;

    microstructure_coupling = std::make_unique<MicrostructureCoupling>(
      parameters, *background_mesh, *volume_elasticity, timer, pcout);
    microstructure_coupling->setup();
  }
} // namespace ssc
