#include <deal.II/base/timer.h>

#include <cmath>
#include <iomanip>
#include <memory>

#include <ssc/output/field_output.h>
#include <ssc/output/run_output.h>
#include <ssc/scenes/depth_error_estimator.h>
#include <ssc/scenes/indentation_scene.h>
#include <ssc/scenes/mechanics_model.h>
#include <ssc/scenes/punch_hold.h>
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

    std::unique_ptr<DepthErrorEstimator> depth_error;
    {
      TimerOutput::Scope t(scene.timer(), "error estimate");
      depth_error = DepthErrorEstimator::create(parameters, mpi_communicator);
      if (depth_error)
        {
          scene.pcout() << "Depth error estimate: " << depth_error->method()
                        << " (" << depth_error->n_dofs() << " DoFs)"
                        << std::endl;
          depth_error->prepare(scene.pcout());
        }
    }

    // in time (creep, relaxation) the steps are times, each with its load
    std::unique_ptr<PunchHold> hold;
    if (parameters.time.enabled())
      hold = std::make_unique<PunchHold>(parameters);
    const std::vector<double> loads =
      hold ? hold->loads() : parameters.punch.loads();
    const auto on_step = [&](const unsigned int step) {
      record.record(step, loads[step]);
      if (hold)
        scene.pcout() << "t = " << std::setprecision(6) << hold->times()[step]
                      << " s: ";
      if (depth_error)
        {
          TimerOutput::Scope t(scene.timer(), "error estimate");
          record.record_depth_error(
            depth_error->error(system, step, loads[step], record.last_depth()),
            depth_error->method(),
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
    if (hold)
      hold->follow(driver, loading, system, on_step);
    else
      follow_punch_path(driver, loading, parameters, on_step);
    {
      TimerOutput::Scope t(scene.timer(), "output");
      record.write_tables(loads, scene.output());
    }

    nlohmann::ordered_json summary =
      scene.summary(system.field().dof_handler().n_dofs(),
                    model.mesh().triangulation().n_global_active_cells());
    const IndentationResult result = record.add_to_summary(summary);
    if (hold)
      {
        hold->record(result, summary, scene.output());
        hold->print(result, scene.pcout());
      }
    scene.output().write_summary(summary);
    scene.print_wall_times();
    return result;
  }
} // namespace ssc
