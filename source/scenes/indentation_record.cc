#include <cmath>
#include <iomanip>

#include <ssc/scenes/indentation_record.h>
#include <ssc/scenes/indentation_scene.h>

namespace ssc
{
  namespace
  {
    /// The points of the surface profile: along y = 0 over the patch.
    std::vector<Point<3>>
    surface_profile_points(const Parameters &parameters)
    {
      return profile_points(parameters.punch,
                            std::min(parameters.mesh.patch_length_x,
                                     parameters.mesh.patch_length_y),
                            parameters.mesh.symmetry == MeshSymmetry::quarter);
    }
  } // namespace


  IndentationRecord::IndentationRecord(const Parameters        &parameters,
                                       MechanicsModel          &model,
                                       PunchLoading            &loading,
                                       const QuasiStaticDriver &driver,
                                       ConditionalOStream      &pcout)
    : parameters(parameters)
    , model(model)
    , loading(loading)
    , driver(driver)
    , pcout(pcout)
    , locator(model.mesh().triangulation(), model.system().field().mapping())
    , profile_at(surface_profile_points(parameters))
    , profile_locations(parameters.punch.profile_length > 0 ?
                          locator.locate(profile_at) :
                          std::vector<PointLocation>())
    , centre_axis(parameters.layers, locator)
  {}


  void
  IndentationRecord::record(const unsigned int step, const double load)
  {
    const bool           verbose = !parameters.run.test_mode;
    const ElasticSystem &system  = model.system();
    const double         force   = loading.force(load);
    const double         depth   = loading.depth(load);
    if (driver.linear() && step == 0)
      {
        // the unit load's response, of which every step is a multiple
        const double unit_force = loading.reaction_force() / load;
        pcout << "Unit load (" << (loading.force_control() ? "1 N" : "1 mm")
              << "): " << std::setprecision(6) << "force " << unit_force
              << " N, depth " << depth / load << " mm";
        if (verbose)
          pcout << ", " << driver.statistics()[0].linear_iterations
                << " CG iterations";
        pcout << std::endl;
        tie_balance = std::abs(unit_force - 1.);
        if (loading.force_control() && verbose)
          pcout << "Force balance of the tied punch: |reaction - 1 N| = "
                << tie_balance << " N" << std::endl;
      }
    if (const RigidPunchContact *contact = loading.edge_contact())
      {
        const std::string line =
          contact_log.record(*contact, system.field().solution());
        if (verbose)
          pcout << line << std::endl;
      }
    if (const PunchFriction *friction = loading.friction())
      {
        const std::string line =
          friction_log.record(*friction, parameters.mesh.symmetry_factor());
        if (verbose)
          pcout << line << std::endl;
      }
    result.forces.push_back(force);
    result.depths.push_back(depth);
    result.layer_strains.push_back(centre_axis.evaluate(system.field()));
    profiles.push_back(
      vertical_displacements(profile_locations, system.field()));
  }


  void
  IndentationRecord::record_depth_error(const double       depth_change,
                                        const std::string &method,
                                        const types::global_dof_index dofs)
  {
    result.depth_error_estimates.push_back(depth_change);
    depth_error_method = method;
    depth_error_dofs   = dofs;
  }


  void
  IndentationRecord::print_step(const unsigned int step,
                                const unsigned int n_steps) const
  {
    const LayerStack     &stack      = parameters.layers;
    const StepStatistics &statistics = driver.statistics().back();
    pcout << "Load step " << step + 1 << " of " << n_steps << ": force "
          << std::setprecision(6) << result.forces.back() << " N, depth "
          << result.depths.back() << " mm";
    if (result.depth_error_estimates.size() == result.depths.size())
      {
        const double change = result.depth_error_estimates.back();
        if (std::isnan(change))
          pcout << " (no error estimate)";
        else
          pcout << " (estimated error " << std::showpos << change
                << std::noshowpos << " mm)";
      }
    if (parameters.punch.shape == PunchShape::rectangle)
      {
        pcout << ", layer strains under the centre";
        for (unsigned int l = 0; l < stack.n_layers(); ++l)
          pcout << (l > 0 ? ", " : " ") << stack.layer(l).name << ' '
                << result.layer_strains.back()[l];
      }
    if (!parameters.run.test_mode && !driver.linear())
      pcout << " (" << statistics.increments << " increments, "
            << statistics.cuts << " cut, " << statistics.newton_iterations
            << " Newton iterations, " << statistics.linear_iterations
            << " CG iterations)";
    pcout << std::endl;
  }


  void
  IndentationRecord::write_tables(const std::vector<double> &loads,
                                  RunOutput                 &output)
  {
    const PunchParameters &punch  = parameters.punch;
    const ElasticSystem   &system = model.system();
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
    write_force_displacement(result.forces,
                             result.depths,
                             driver.statistics(),
                             output);
  }


  IndentationResult
  IndentationRecord::add_to_summary(nlohmann::ordered_json &summary) const
  {
    const PunchParameters &punch    = parameters.punch;
    const LayerStack      &stack    = parameters.layers;
    IndentationResult      measured = result;
    measured.dofs      = model.system().field().dof_handler().n_dofs();
    measured.stiffness = result.forces.front() / result.depths.front();
    const Layer &top   = stack.layer(0);
    // a rectangle's reference: the disk of equal area
    measured.half_space_stiffness =
      IndentationScene::half_space_stiffness(std::sqrt(punch.area() / M_PI),
                                             top.youngs_modulus,
                                             top.poisson_ratio,
                                             punch.contact);
    pcout << "Stiffness: " << std::setprecision(6) << measured.stiffness
          << " N/mm (half-space reference for the top layer's material: "
          << measured.half_space_stiffness << " N/mm)" << std::endl;

    summary["embedded"] = model.coupling().embedded_summary();
    std::string models;
    for (unsigned int l = 0; l < stack.n_layers(); ++l)
      models += (l > 0 ? ", " : "") + stack.layer(l).name + ": " +
                stack.layer(l).material_model;
    summary["discretisation"] = {{"degree", parameters.elasticity.degree},
                                 {"formulation",
                                  to_string(parameters.elasticity.formulation)},
                                 {"material_model", models}};
    summary["solver"]         = driver.summary();
    summary["control"]        = to_string(punch.control);
    summary["contact"]        = to_string(punch.contact);
    if (loading.edge_contact())
      summary["edge_contact"] =
        contact_log.summary(punch.edge_radius, punch.contact_penalty);
    if (const PunchFriction *friction = loading.friction())
      summary["friction"] = friction_log.summary(*friction,
                                                 punch.friction_coefficient,
                                                 punch.friction_penalty);
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
        for (const auto &step : result.layer_strains)
          per_step.push_back(step[l]);
        strains[stack.layer(l).name] = per_step;
      }
    summary["layer_strain_under_centre_per_step"] = strains;
    summary["force_N"]                            = result.forces;
    summary["depth_mm"]                           = result.depths;
    if (!result.depth_error_estimates.empty())
      {
        std::vector<double> size;
        for (const double change : result.depth_error_estimates)
          size.push_back(std::abs(change));
        summary["depth_error_estimate_mm"]  = result.depth_error_estimates;
        summary["depth_uncertainty_mm"]     = size;
        summary["depth_uncertainty_method"] = depth_error_method;
        summary["depth_uncertainty_dofs"]   = depth_error_dofs;
      }
    summary["stiffness_N_per_mm"]            = measured.stiffness;
    summary["half_space_stiffness_N_per_mm"] = measured.half_space_stiffness;
    if (loading.force_control() && driver.linear())
      summary["tie_force_balance_error_N"] = tie_balance;
    return measured;
  }
} // namespace ssc
