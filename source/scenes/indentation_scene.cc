#include <deal.II/base/timer.h>

#include <cmath>
#include <iomanip>

#include <ssc/output/field_output.h>
#include <ssc/output/run_output.h>
#include <ssc/output/volume_output.h>
#include <ssc/scenes/indentation_output.h>
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
    const RunParameters   &run   = parameters.run;
    const PunchParameters &punch = parameters.punch;
    SceneRun               scene(parameters, mpi_communicator, "indentation");
    MechanicsModel         model(parameters, scene);
    ElasticSystem         &system = model.system();
    TimerOutput           &timer  = scene.timer();
    ConditionalOStream    &pcout  = scene.pcout();
    RunOutput             &output = scene.output();
    PunchLoading           loading(parameters, system, timer, pcout);
    QuasiStaticDriver driver(system, parameters.newton, pcout, !run.test_mode);
    const FieldOutput field_output(system,
                                   model.coupling(),
                                   driver.linear() ? Kinematics::small_strain :
                                                     Kinematics::finite_strain);

    const PointLocator locator(model.mesh().triangulation(),
                               system.field().mapping());
    const auto         profile_at =
      profile_points(punch,
                     std::min(parameters.mesh.patch_length_x,
                              parameters.mesh.patch_length_y),
                     parameters.mesh.symmetry == MeshSymmetry::quarter);
    const auto profile_locations = punch.profile_length > 0 ?
                                     locator.locate(profile_at) :
                                     std::vector<PointLocation>();
    // each layer's compression under the punch centre, as an ultrasound
    // image measures it
    const LayerStack                &stack = parameters.layers;
    const CentreAxisStrains          centre_axis(stack, locator);
    std::vector<std::vector<double>> layer_strains;
    const std::vector<double>        loads = punch.loads();
    std::vector<double>              depths, forces;
    std::vector<std::vector<double>> profiles;
    std::vector<double>              contact_areas, contact_penetrations;
    std::vector<unsigned int>        sticking, slipping;
    std::vector<double>              friction_normal_forces;
    double                           tie_balance = 0;

    const auto on_step = [&](const unsigned int step) {
      const double load  = loads[step];
      const double force = loading.force(load);
      const double depth = loading.depth(load);
      if (driver.linear() && step == 0)
        {
          // the unit load's response, of which every step is a multiple
          const double unit_force = loading.reaction_force() / load;
          pcout << "Unit load (" << (loading.force_control() ? "1 N" : "1 mm")
                << "): " << std::setprecision(6) << "force " << unit_force
                << " N, depth " << depth / load << " mm";
          if (!run.test_mode)
            pcout << ", " << driver.statistics()[0].linear_iterations
                  << " CG iterations";
          pcout << std::endl;
          tie_balance = std::abs(unit_force - 1.);
          if (loading.force_control() && !run.test_mode)
            pcout << "Force balance of the tied punch: |reaction - 1 N| = "
                  << tie_balance << " N" << std::endl;
        }
      if (const RigidPunchContact *contact = loading.edge_contact())
        {
          const auto [area, penetration] =
            contact->contact_state(system.field().solution());
          contact_areas.push_back(area);
          contact_penetrations.push_back(penetration);
          if (!run.test_mode)
            pcout << "  edge contact: " << area
                  << " mm^2 of skin, largest penetration " << penetration
                  << " mm" << std::endl;
        }
      if (const PunchFriction *friction = loading.friction())
        {
          const FrictionState &state = friction->accepted_state();
          sticking.push_back(state.sticking);
          slipping.push_back(state.slipping);
          // the whole punch's, as the force
          friction_normal_forces.push_back(state.normal_force *
                                           parameters.mesh.symmetry_factor());
          if (!run.test_mode)
            pcout << "  friction: " << state.sticking << " nodes stick, "
                  << state.slipping << " slip, " << state.free << " not pressed"
                  << std::endl;
        }
      forces.push_back(force);
      depths.push_back(depth);
      layer_strains.push_back(centre_axis.evaluate(system.field()));
      profiles.push_back(
        vertical_displacements(profile_locations, system.field()));
      if (run.write_fields)
        {
          TimerOutput::Scope t(timer, "output");
          field_output.write(output, step + 1, force);
        }
      const StepStatistics &statistics = driver.statistics().back();
      pcout << "Load step " << step + 1 << " of " << loads.size() << ": force "
            << std::setprecision(6) << force << " N, depth " << depth << " mm";
      if (punch.shape == PunchShape::rectangle)
        {
          pcout << ", layer strains under the centre";
          for (unsigned int l = 0; l < stack.n_layers(); ++l)
            pcout << (l > 0 ? ", " : " ") << stack.layer(l).name << ' '
                  << layer_strains.back()[l];
        }
      if (!run.test_mode && !driver.linear())
        pcout << " (" << statistics.increments << " increments, "
              << statistics.cuts << " cut, " << statistics.newton_iterations
              << " Newton iterations, " << statistics.linear_iterations
              << " CG iterations)";
      pcout << std::endl;
    };
    driver.run(
      loads,
      [&loading](const double load) { loading.apply(load); },
      loads.front() / parameters.newton.initial_steps,
      LoadDependence::right_hand_side,
      on_step);

    {
      TimerOutput::Scope t(timer, "output");
      if (punch.section)
        {
          write_section(
            parameters, locator, system.field(), system.materials(), output);
          if (const Microstructure *microstructure =
                model.coupling().get_microstructure())
            write_septa_section(
              parameters, *microstructure, locator, system.field(), output);
        }
      if (punch.profile_length > 0)
        write_surface_profile(punch, profile_at, loads, profiles, output);
      write_force_displacement(forces, depths, driver.statistics(), output);
    }

    const double stiffness = forces.front() / depths.front();
    const Layer &top       = parameters.layers.layer(0);
    // a rectangle's reference: the disk of equal area
    const double reference =
      half_space_stiffness(std::sqrt(punch.area() / M_PI),
                           top.youngs_modulus,
                           top.poisson_ratio,
                           punch.contact);
    pcout << "Stiffness: " << std::setprecision(6) << stiffness
          << " N/mm (half-space reference for the top layer's material: "
          << reference << " N/mm)" << std::endl;

    nlohmann::ordered_json summary =
      scene.summary(system.field().dof_handler().n_dofs(),
                    model.mesh().triangulation().n_global_active_cells());
    summary["embedded"] = model.coupling().embedded_summary();
    std::string models;
    for (unsigned int l = 0; l < parameters.layers.n_layers(); ++l)
      models += (l > 0 ? ", " : "") + parameters.layers.layer(l).name + ": " +
                to_string(parameters.layers.layer(l).model);
    summary["discretisation"] = {{"degree", parameters.elasticity.degree},
                                 {"formulation",
                                  to_string(parameters.elasticity.formulation)},
                                 {"material_model", models}};
    summary["solver"]         = driver.summary();
    summary["control"]        = to_string(punch.control);
    summary["contact"]        = to_string(punch.contact);
    if (loading.edge_contact())
      summary["edge_contact"] = {{"edge_radius_mm", punch.edge_radius},
                                 {"penalty_factor", punch.contact_penalty},
                                 {"area_mm2_per_step", contact_areas},
                                 {"max_penetration_mm_per_step",
                                  contact_penetrations}};
    if (loading.friction())
      summary["friction"] = {
        {"coefficient", punch.friction_coefficient},
        {"penalty_factor", punch.friction_penalty},
        {"nodes", loading.friction()->n_nodes()},
        {"sticking_nodes_per_step", sticking},
        {"slipping_nodes_per_step", slipping},
        {"normal_force_N_per_step", friction_normal_forces},
        {"note",
         "normal forces: the tie's reactions the last solve of the step "
         "used, settled to 2 % (staggered)"}};
    summary["symmetry"]       = to_string(parameters.mesh.symmetry);
    summary["punch_shape"]    = to_string(punch.shape);
    summary["punch_area_mm2"] = punch.area();
    if (punch.shape == PunchShape::circle)
      summary["punch_radius_mm"] = punch.radius;
    else
      {
        summary["punch_length_mm"] = punch.length;
        summary["punch_width_mm"]  = punch.width;
      }
    nlohmann::ordered_json strains;
    for (unsigned int l = 0; l < stack.n_layers(); ++l)
      {
        std::vector<double> per_step;
        for (const auto &step : layer_strains)
          per_step.push_back(step[l]);
        strains[stack.layer(l).name] = per_step;
      }
    summary["layer_strain_under_centre_per_step"] = strains;
    summary["force_N"]                            = forces;
    summary["depth_mm"]                           = depths;
    if (!punch.depth_uncertainty.empty())
      summary["depth_uncertainty_mm"] = punch.depth_uncertainty;
    summary["stiffness_N_per_mm"]            = stiffness;
    summary["half_space_stiffness_N_per_mm"] = reference;
    if (loading.force_control() && driver.linear())
      summary["tie_force_balance_error_N"] = tie_balance;
    output.write_summary(summary);
    scene.print_wall_times();
    return {system.field().dof_handler().n_dofs(),
            depths,
            forces,
            stiffness,
            reference,
            layer_strains};
  }
} // namespace ssc
