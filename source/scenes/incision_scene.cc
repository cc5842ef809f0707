#include <deal.II/base/timer.h>

#include <array>
#include <cmath>
#include <iomanip>
#include <limits>
#include <memory>
#include <sstream>

#include <ssc/base/surface_expression.h>
#include <ssc/materials/gasser_ogden_holzapfel_material.h>
#include <ssc/output/field_output.h>
#include <ssc/scenes/closure.h>
#include <ssc/scenes/incision_scene.h>
#include <ssc/scenes/mechanics_model.h>
#include <ssc/scenes/quasi_static_driver.h>
#include <ssc/scenes/scene_run.h>
#include <ssc/scenes/support_conditions.h>
#include <ssc/scenes/wound_record.h>

namespace ssc
{
  namespace
  {
    /// The angle (degrees from x) of Langer's lines at the patch centre
    /// where the skin's law has them, NaN otherwise.
    double
    langer_line_angle_at_centre(const Parameters &parameters)
    {
      const Layer &skin  = parameters.layers.layer(0);
      const auto *fibres = dynamic_cast<const GasserOgdenHolzapfelParameters *>(
        &parameters.materials.of(skin.name, skin.material_model));
      if (fibres == nullptr)
        return std::numeric_limits<double>::quiet_NaN();
      return parse_surface_expression(fibres->langer_line_angle,
                                      "Langer line angle")
        ->value(Point<2>());
    }

    /**
     * The skin's plane tension far from the cut, N/m, along x and y: its law
     * (at full pre-tension) at F = diag(1, 1, lambda), the sides held and
     * lambda such that its free surface carries no normal stress, the
     * in-plane Cauchy stress times the deformed thickness. The number to
     * compare with in vivo skin tension (Flynn et al. 2011).
     */
    std::array<double, 2>
    far_field_skin_tension(const Material &skin, const double thickness)
    {
      const Point<3> X(0, 0, -thickness / 2);
      const auto     stress = [&](const double lambda) {
        Tensor<2, 3> F = unit_symmetric_tensor<3>();
        F[2][2]        = lambda;
        return skin.cauchy_stress(X, F);
      };
      double low = 0.2, high = 5.;
      AssertThrow(stress(low)[2][2] < 0 && stress(high)[2][2] > 0,
                  ExcMessage("The skin's free-surface thickness under its "
                             "pre-tension is not between 0.2 and 5 times the "
                             "imaged one."));
      for (unsigned int k = 0; k < 100 && high - low > 1e-12; ++k)
        {
          const double mid                     = (low + high) / 2;
          (stress(mid)[2][2] < 0 ? low : high) = mid;
        }
      const double                lambda = (low + high) / 2;
      const SymmetricTensor<2, 3> sigma  = stress(lambda);
      // N/mm -> N/m
      return {{1e3 * sigma[0][0] * thickness * lambda,
               1e3 * sigma[1][1] * thickness * lambda}};
    }
  } // namespace


  std::vector<WoundShape>
  IncisionScene::run()
  {
    SceneRun                  scene(parameters, mpi_communicator, "incision");
    const IncisionParameters &cut_parameters = parameters.incision;
    const auto                equal_steps    = [](const unsigned int n) {
      std::vector<double> fractions;
      for (unsigned int step = 1; step <= n; ++step)
        fractions.push_back(double(step) / n);
      return fractions;
    };
    const std::vector<double> pretension =
      equal_steps(cut_parameters.load_steps);
    const std::vector<double> closing =
      equal_steps(cut_parameters.closure.load_steps);
    const double first_increment = 1. / parameters.newton.initial_steps;

    WoundRecord              record(parameters,
                       langer_line_angle_at_centre(parameters),
                       scene.pcout());
    std::array<double, 2>    tension = {{0, 0}};
    types::global_dof_index  dofs    = 0;
    types::global_cell_index cells   = 0;
    for (unsigned int direction = 0; direction < cut_parameters.n_directions();
         ++direction)
      {
        const Incision incision =
          cut_parameters.incision(parameters.layers, direction);
        record.begin_model(incision);
        MechanicsModel              model(parameters, scene, incision);
        ElasticSystem              &system = model.system();
        std::unique_ptr<SutureTies> sutures;
        if (cut_parameters.closure.enabled())
          {
            sutures = std::make_unique<SutureTies>(
              find_sutures(system.field(),
                           incision,
                           cut_parameters.closure.suture_spacing,
                           cut_parameters.closure.bite_width),
              cut_parameters.closure.suture_stiffness,
              system.field().locally_owned_dofs());
            system.attach(*sutures);
          }
        {
          TimerOutput::Scope t(scene.timer(), "setup");
          system.setup(support_conditions(parameters.elasticity.sides));
        }
        QuasiStaticDriver driver(system,
                                 parameters.newton,
                                 scene.pcout(),
                                 !parameters.run.test_mode);
        driver.run(
          pretension,
          [&system](const double f) { system.set_prestretch_fraction(f); },
          first_increment,
          LoadDependence::tangent,
          [&](const unsigned int k) {
            TimerOutput::Scope t(scene.timer(), "output");
            record.record_wound(k + 1,
                                pretension[k],
                                measure_wound(system.field(), incision));
          });

        // the sutures draw the opened wound's lips together
        nlohmann::ordered_json closure_solver;
        if (sutures)
          {
            const TrilinosWrappers::MPI::Vector opened =
              system.field().solution();
            sutures->start(opened);
            scene.pcout() << "  closing with " << sutures->sutures().size()
                          << " sutures" << std::endl;
            QuasiStaticDriver closure(system,
                                      parameters.newton,
                                      scene.pcout(),
                                      !parameters.run.test_mode);
            closure.run(
              closing,
              [&sutures](const double t) { sutures->set_fraction(t); },
              first_increment,
              LoadDependence::right_hand_side,
              [&](const unsigned int k) {
                TimerOutput::Scope t(scene.timer(), "output");
                record.record_closure(
                  k + 1, measure_closure(system, *sutures, opened, closing[k]));
              });
            closure_solver = closure.summary();
          }
        if (parameters.run.write_fields)
          {
            TimerOutput::Scope t(scene.timer(), "output");
            FieldOutput(system, model.coupling(), Kinematics::finite_strain)
              .write(scene.output(), direction + 1, direction);
          }
        record.end_model(driver.summary(), closure_solver);
        tension =
          far_field_skin_tension(system.materials()[0],
                                 parameters.layers.layer(0).thickness(0, 0));
        dofs  = system.field().dof_handler().n_dofs();
        cells = model.mesh().triangulation().n_global_active_cells();
      }

    nlohmann::ordered_json summary = scene.summary(dofs, cells);
    record.add_to_summary(summary, tension);
    {
      TimerOutput::Scope t(scene.timer(), "output");
      record.write_tables(scene.output());
      scene.output().write_summary(summary);
    }
    scene.pcout() << "Skin tension far from the cut: " << tension[0]
                  << " N/m along x, " << tension[1] << " N/m along y"
                  << std::endl;
    scene.print_wall_times();
    return record.wounds();
  }
} // namespace ssc
