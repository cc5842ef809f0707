#include <deal.II/base/timer.h>

#include <algorithm>
#include <iomanip>
#include <sstream>

#include <ssc/output/field_output.h>
#include <ssc/scenes/growth_record.h>
#include <ssc/scenes/growth_region.h>
#include <ssc/scenes/growth_scene.h>
#include <ssc/scenes/mechanics_model.h>
#include <ssc/scenes/quasi_static_driver.h>
#include <ssc/scenes/scene_run.h>
#include <ssc/scenes/support_conditions.h>

namespace ssc
{
  namespace
  {
    /**
     * Samples the growth of the selected fat on @p system (and on the
     * septa, where they grow with it), finds the ratio g that adds the
     * target volume and says so on @p pcout.
     */
    GrowthSelection
    select_growing_fat(const Parameters       &parameters,
                       ElasticSystem          &system,
                       MicrostructureCoupling &coupling,
                       ConditionalOStream     &pcout)
    {
      const GrowthParameters &growth = parameters.growth;
      GrowthSelection         selection;
      const GrowthRegion      region(parameters.layers,
                                growth,
                                coupling.get_microstructure());
      system.growth().sample(system.field(),
                             [&region](const Point<3>    &p,
                                       const unsigned int layer) {
                               return region(p, layer);
                             });
      if (coupling.get_microstructure() != nullptr && growth.septum_growth > 0)
        {
          std::vector<double> septum_weights;
          for (const Septum &septum : coupling.get_microstructure()->septa())
            septum_weights.push_back(region.septum_weight(septum));
          coupling.grow_septa(
            system.growth(),
            [septum_weights](const unsigned int septum) {
              return septum_weights[septum];
            },
            growth.septum_growth);
        }
      const std::vector<double> &weights = selection.lobule_weights =
        region.lobule_weights();
      selection.selected_volume = system.growth().volume(system.field());
      if (!(selection.selected_volume > 0) && region.n_lobules_in_region() > 0)
        {
          std::ostringstream none;
          none << "Growth/Growing lobule fraction = "
               << growth.growing_lobule_fraction << " lets none of the "
               << region.n_lobules_in_region()
               << " lobules in the growth region grow (draws of "
                  "Growth/Random seed): raise the fraction.";
          AssertThrow(false, ExcMessage(none.str()));
        }
      AssertThrow(selection.selected_volume > 0,
                  ExcMessage("Growth: no material grows (no lobule of "
                             "Growth/Layers has its centroid in the region, "
                             "and no point of those layers lies in it)."));
      selection.growth_ratio = growth.added_volume / selection.selected_volume;
      if (!(selection.growth_ratio <= GrowthParameters::max_growth_ratio))
        {
          std::ostringstream ratio;
          ratio << "Growth/Added volume = " << growth.added_volume
                << " mm^3 over the " << selection.selected_volume
                << " mm^3 of growing fat (weighted) is a growth ratio g = "
                << selection.growth_ratio
                << ", above the largest accepted, g = "
                << GrowthParameters::max_growth_ratio
                << " (fat eleven times its volume): lower the Added volume "
                   "or let more fat grow (Growth/Region, Layers, Growing "
                   "lobule fraction).";
          AssertThrow(false, ExcMessage(ratio.str()));
        }
      pcout << "Growth: " << weights.size() << " lobules, "
            << std::setprecision(6) << selection.selected_volume
            << " mm^3 of fat grow by g = " << selection.growth_ratio
            << " (added volume " << growth.added_volume << " mm^3)";
      if (growth.lobule_growth_spread > 0 && !weights.empty())
        pcout << ", lobule weights "
              << *std::min_element(weights.begin(), weights.end()) << " to "
              << *std::max_element(weights.begin(), weights.end());
      pcout << std::endl;
      return selection;
    }
  } // namespace


  GrowthResult
  GrowthScene::run()
  {
    const GrowthParameters &growth = parameters.growth;
    SceneRun                scene(parameters, mpi_communicator, "growth");
    MechanicsModel          model(parameters, scene);
    ElasticSystem          &system = model.system();
    GrowthSelection         selection;
    {
      TimerOutput::Scope t(scene.timer(), "setup");
      system.setup(support_conditions(parameters.elasticity.sides));
      selection =
        select_growing_fat(parameters, system, model.coupling(), scene.pcout());
    }
    QuasiStaticDriver driver(system,
                             parameters.newton,
                             scene.pcout(),
                             !parameters.run.test_mode);
    GrowthRecord record(parameters, model, driver, scene.pcout(), selection);
    const FieldOutput   field_output(system,
                                   model.coupling(),
                                   driver.linear() ? Kinematics::small_strain :
                                                       Kinematics::finite_strain);
    std::vector<double> fractions;
    for (unsigned int step = 1; step <= growth.load_steps; ++step)
      fractions.push_back(double(step) / growth.load_steps);
    if (driver.linear())
      scene.pcout() << "Linear elasticity: one solve for the whole growth";
    driver.run(
      fractions,
      [&](const double fraction) {
        system.growth().set_scale(fraction * selection.growth_ratio);
      },
      1. / parameters.newton.initial_steps,
      LoadDependence::tangent,
      [&](const unsigned int k) {
        record.record(k, fractions[k]);
        if (parameters.run.write_fields)
          {
            TimerOutput::Scope t(scene.timer(), "output");
            field_output.write(scene.output(), k + 1, fractions[k]);
          }
      });
    {
      TimerOutput::Scope t(scene.timer(), "output");
      record.write_tables(scene.output());
    }

    nlohmann::ordered_json summary =
      scene.summary(system.field().dof_handler().n_dofs(),
                    model.mesh().triangulation().n_global_active_cells());
    const GrowthResult result = record.add_to_summary(summary);
    scene.output().write_summary(summary);
    scene.print_wall_times();
    return result;
  }
} // namespace ssc
