#include <ssc/scenes/mechanics_model.h>
#include <ssc/scenes/model_size.h>

namespace ssc
{
  MechanicsModel::MechanicsModel(const Parameters &parameters,
                                 SceneRun         &scene,
                                 const Incision   &incision)
    : MechanicsModel(parameters,
                     scene.communicator(),
                     scene.timer(),
                     scene.pcout(),
                     scene.timed_pcout(),
                     incision)
  {}


  MechanicsModel::MechanicsModel(const Parameters   &parameters,
                                 const MPI_Comm      mpi_communicator,
                                 TimerOutput        &timer,
                                 ConditionalOStream &pcout,
                                 ConditionalOStream &timed_pcout,
                                 const Incision     &incision)
  {
    background_mesh = std::make_unique<BackgroundMesh>(
      parameters.layers,
      parameters.mesh,
      mpi_communicator,
      parameters.limits,
      parameters.elasticity.linear_solver.preconditioner ==
        DisplacementPreconditioner::gmg,
      incision);
    {
      TimerOutput::Scope t(timer, "mesh");
      background_mesh->build();
    }
    pcout << "Mesh: "
          << background_mesh->triangulation().n_global_active_cells()
          << " hexahedra over " << parameters.layers.n_layers() << " layers"
          << std::endl;

    elastic_system =
      std::make_unique<ElasticSystem>(*background_mesh,
                                      LayerMaterials(parameters.layers,
                                                     parameters.materials),
                                      parameters.elasticity,
                                      timer,
                                      &timed_pcout);
    {
      TimerOutput::Scope t(timer, "setup");
      elastic_system->field().distribute_dofs();
    }
    // local refinement is known only now: check the real DoF count before
    // the matrix and the preconditioner are built
    const double dofs = elastic_system->field().dof_handler().n_dofs();
    ResourceLimits::require(dofs,
                            parameters.limits.max_dofs,
                            "The number of DoFs",
                            "Max DoFs",
                            parameters.mesh.coarsening_advice());
    parameters.limits.require_memory(
      dofs * bytes_per_dof(parameters.elasticity.degree),
      "The linear system (" + std::to_string(static_cast<long>(dofs)) +
        " DoFs)",
      parameters.mesh.coarsening_advice() + ", or lower Elasticity/Degree");
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
    microstructure_coupling->setup(&timed_pcout);
  }
} // namespace ssc
