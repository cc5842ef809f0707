#include <deal.II/base/timer.h>

#include <cmath>
#include <iomanip>
#include <memory>

#include <ssc/output/field_output.h>
#include <ssc/output/run_output.h>
#include <ssc/scenes/coarser_mesh_depth_estimate.h>
#include <ssc/scenes/enriched_depth_estimate.h>
#include <ssc/scenes/indentation_scene.h>
#include <ssc/scenes/mechanics_model.h>
#include <ssc/scenes/punch_loading.h>
#include <ssc/scenes/quasi_static_driver.h>
#include <ssc/scenes/scene_run.h>

namespace ssc
{
  double
  IndentationScene::half_space_stiffness(const double       a,
                                         const double       E,
                                         const double       nu,
                                         const PunchContact contact)
  {
    const double frictionless = 2. * a * E / (1. - nu * nu);
    if (contact == PunchContact::frictionless)
      return frictionless;
    // (1 - nu) ln(3 - 4 nu) / (1 - 2 nu) -> 1 as nu -> 1/2
    const double ratio = std::abs(1. - 2. * nu) < 1e-8 ?
                           1. :
                           (1. - nu) * std::log(3. - 4. * nu) / (1. - 2. * nu);
    return frictionless * ratio;
  }


  IndentationResult
  IndentationScene::run()
  {
    SceneRun          scene(parameters, mpi_communicator, "indentation");
    MechanicsModel    model(parameters, scene);
    ElasticSystem    &system = model.system();
    PunchLoading      loading(parameters, system, scene.timer(), scene.pcout());
    QuasiStaticDriver driver(system,
                             parameters.newton,
                             scene.pcout(),
                             !parameters.run.test_mode);
    const FieldOutput field_output(system,
                                   model.coupling(),
                                   driver.linear() ? Kinematics::small_strain :
                                                     Kinematics::finite_strain);
    IndentationRecord record(parameters, model, loading, driver, scene.pcout());

    std::unique_ptr<EnrichedDepthEstimate> depth_error;
    if (parameters.punch.depth_error_estimate ==
        DepthErrorEstimate::enriched_degree)
      {
        TimerOutput::Scope t(scene.timer(), "error estimate");
        depth_error =
          std::make_unique<EnrichedDepthEstimate>(parameters, mpi_communicator);
        scene.pcout() << "Depth error estimate: a Q2-P0 step of "
                      << depth_error->n_dofs() << " DoFs per force"
                      << std::endl;
      }

    std::unique_ptr<CoarserMeshDepthEstimate> coarser_mesh;
    if (parameters.punch.depth_error_estimate ==
        DepthErrorEstimate::coarser_mesh)
      {
        TimerOutput::Scope t(scene.timer(), "error estimate");
        coarser_mesh =
          std::make_unique<CoarserMeshDepthEstimate>(parameters,
                                                     mpi_communicator);
        scene.pcout() << "Depth error estimate: the path on the mesh with "
                         "one global refinement fewer ("
                      << coarser_mesh->n_dofs() << " DoFs)" << std::endl;
        coarser_mesh->solve(scene.pcout());
      }

    const std::vector<double> loads   = parameters.punch.loads();
    const auto                on_step = [&](const unsigned int step) {
      record.record(step, loads[step]);
      if (coarser_mesh)
        record.record_depth_error(coarser_mesh->error(step,
                                                      record.last_depth()),
                                  CoarserMeshDepthEstimate::method(),
                                  coarser_mesh->n_dofs());
      if (depth_error)
        {
          TimerOutput::Scope t(scene.timer(), "error estimate");
          record.record_depth_error(depth_error->depth_change(system,
                                                              loads[step]),
                                    EnrichedDepthEstimate::method(),
                                    depth_error->n_dofs());
          if (!depth_error->failure_reason().empty())
            scene.pcout() << "  no depth error estimate at " << loads[step]
                          << " N: " << depth_error->failure_reason()
                          << std::endl;
        }
      if (parameters.run.write_fields)
        {
          TimerOutput::Scope t(scene.timer(), "output");
          field_output.write(scene.output(), step + 1, record.last_force());
        }
      record.print_step(step, loads.size());
    };
    driver.run(
      loads,
      [&loading](const double load) { loading.apply(load); },
      loads.front() / parameters.newton.initial_steps,
      LoadDependence::right_hand_side,
      on_step);
    {
      TimerOutput::Scope t(scene.timer(), "output");
      record.write_tables(loads, scene.output());
    }

    nlohmann::ordered_json summary =
      scene.summary(system.field().dof_handler().n_dofs(),
                    model.mesh().triangulation().n_global_active_cells());
    const IndentationResult result = record.add_to_summary(summary);
    scene.output().write_summary(summary);
    scene.print_wall_times();
    return result;
  }
} // namespace ssc
