#include <deal.II/base/function.h>
#include <deal.II/base/timer.h>

#include <ssc/background_mesh.h>
#include <ssc/embedding/point_locator.h>
#include <ssc/mechanics/corotational_material.h>
#include <ssc/mechanics/linear_elastic_material.h>
#include <ssc/mechanics/microstructure_coupling.h>
#include <ssc/mechanics/neo_hookean_material.h>
#include <ssc/mechanics/newton_solver.h>
#include <ssc/mechanics/rigid_punch_contact.h>
#include <ssc/mechanics/volume_elasticity.h>
#include <ssc/output.h>
#include <ssc/scenes/indentation_scene.h>
#include <ssc/scenes/mechanics_model.h>
#include <ssc/scenes/scene_run.h>
#include <ssc/scenes/support_conditions.h>

#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>

namespace ssc
{
  IndentationScene::IndentationScene(const Parameters &parameters,
                                     const MPI_Comm    mpi_communicator)
    : parameters(parameters)
    , mpi_communicator(mpi_communicator)
  {}


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


  namespace
  {
    /// The points of the surface profile: y = 0, z = 0, centred in x.
    std::vector<Point<3>>
    profile_points(const PunchParameters &punch, const double patch_length)
    {
      const double          L = std::min(punch.profile_length, patch_length);
      const unsigned int    n = punch.profile_points;
      std::vector<Point<3>> points;
      for (unsigned int i = 0; i < n; ++i)
        points.emplace_back(-L / 2 + L * i / (n - 1), 0., 0.);
      return points;
    }


    /// u_z at @p points for the current solution.
    std::vector<double>
    vertical_displacements(const std::vector<PointLocation> &locations,
                           const VolumeElasticity           &elasticity)
    {
      std::vector<Tensor<1, 3>> u;
      std::vector<Tensor<2, 3>> gradient;
      elasticity.evaluate_at(locations, u, gradient);
      std::vector<double> uz(u.size());
      for (unsigned int i = 0; i < u.size(); ++i)
        uz[i] = u[i][2];
      return uz;
    }


    /// Writes surface_profile.csv: x, then u_z per load step.
    void
    write_surface_profile(const PunchParameters                  &punch,
                          const std::vector<Point<3>>            &points,
                          const std::vector<double>              &loads,
                          const std::vector<std::vector<double>> &profiles,
                          RunOutput                              &output)
    {
      std::ostringstream csv;
      csv << "x_mm";
      for (const double load : loads)
        csv << (punch.control == PunchControl::force ? ",uz_mm_at_F" :
                                                       ",uz_mm_at_depth")
            << load;
      csv << '\n' << std::setprecision(8);
      for (unsigned int i = 0; i < points.size(); ++i)
        {
          csv << points[i][0];
          for (const auto &profile : profiles)
            csv << ',' << profile[i];
          csv << '\n';
        }
      output.write_text("surface_profile.csv", csv.str());
    }


    /// von Mises stress (MPa) of the Cauchy stress of @p layer for the
    /// displacement gradient @p H.
    double
    von_mises_stress(const Layer &layer, const Tensor<2, 3> &H)
    {
      if (layer.model == MaterialModel::linear)
        {
          const LinearElasticMaterial material(layer.youngs_modulus,
                                               layer.poisson_ratio);
          const SymmetricTensor<2, 3> eps = symmetrize(H);
          return von_mises(material.stress(eps, trace(eps)));
        }
      const Tensor<2, 3> F = unit_symmetric_tensor<3>() + H;
      const double       J = determinant(F);
      if (!(J > 0))
        return std::numeric_limits<double>::quiet_NaN();
      // Kirchhoff stress tau = P F^T of the shear part plus J p I
      SymmetricTensor<2, 3> tau;
      double                pressure;
      if (layer.model == MaterialModel::corotational)
        {
          const CorotationalMaterial material(layer.youngs_modulus,
                                              layer.poisson_ratio);
          Tensor<2, 3>               P;
          Tensor<4, 3>               tangent;
          material.isochoric(F, P, tangent);
          tau      = symmetrize(P * transpose(F));
          pressure = material.pressure(J);
        }
      else
        {
          const NeoHookeanMaterial material(layer.youngs_modulus,
                                            layer.poisson_ratio);
          SymmetricTensor<4, 3>    tangent;
          material.isochoric(F, tau, tangent);
          pressure = material.pressure(J);
        }
      return von_mises((tau + J * pressure * unit_symmetric_tensor<3>()) / J);
    }


    /// Writes section.csv: displacement and von Mises stress on a grid of
    /// the plane y = 0 (current solution times @p scale; the scale is for
    /// the linear unit-load response).
    void
    write_section(const Parameters       &parameters,
                  const PointLocator     &locator,
                  const VolumeElasticity &elasticity,
                  const double            scale,
                  RunOutput              &output)
    {
      const LayerStack     &layers = parameters.layers;
      const double          L      = std::min(parameters.punch.profile_length,
                                parameters.mesh.patch_length_x);
      const unsigned int    nx = 121, nz = 81;
      std::vector<Point<3>> points;
      for (unsigned int i = 0; i < nx; ++i)
        {
          const double x = -L / 2 + L * i / (nx - 1);
          const double bottom =
            layers.depth_of_interface(layers.n_layers(), x, 0.);
          for (unsigned int k = 0; k < nz; ++k)
            points.emplace_back(x, 0., -bottom * k / (nz - 1));
        }
      std::vector<Tensor<1, 3>> u;
      std::vector<Tensor<2, 3>> gradient;
      elasticity.evaluate_at(locator.locate(points), u, gradient);
      std::ostringstream csv;
      csv << "x_mm,z_mm,layer,ux_mm,uz_mm,von_mises_kPa\n"
          << std::setprecision(7);
      for (unsigned int k = 0; k < points.size(); ++k)
        {
          const unsigned int l = layers.layer_at(points[k]);
          csv << points[k][0] << ',' << points[k][2] << ',' << l << ','
              << scale * u[k][0] << ',' << scale * u[k][2] << ','
              << 1e3 * von_mises_stress(layers.layer(l), scale * gradient[k])
              << '\n';
        }
      output.write_text("section.csv", csv.str());
    }
  } // namespace


  IndentationResult
  IndentationScene::run()
  {
    const RunParameters &run = parameters.run;
    SceneRun             scene(parameters, mpi_communicator, "indentation");
    RunOutput           &output = scene.output();
    ConditionalOStream  &pcout  = scene.pcout();
    TimerOutput         &timer  = scene.timer();

    MechanicsModel          model(parameters, mpi_communicator, timer, pcout);
    BackgroundMesh         &mesh       = model.mesh();
    VolumeElasticity       &elasticity = model.elasticity();
    MicrostructureCoupling &coupling   = model.coupling();

    // The punch: u_x = u_y = 0 under it if bonded; u_z = -depth
    // (displacement control) or u_z tied to a master (force control).
    const PunchParameters &punch    = parameters.punch;
    const bool             by_force = punch.control == PunchControl::force;
    const double           a        = punch.radius;
    const auto             on_punch = [a](const Point<3> &p) {
      return std::hypot(p[0], p[1]) <= a * (1. + 1e-10);
    };
    std::vector<DirichletCondition> conditions =
      support_conditions(parameters.elasticity.sides);
    std::vector<TiedCondition> ties;
    ComponentMask              punch_components(3, false);
    if (punch.contact == PunchContact::bonded)
      {
        punch_components.set(0, true);
        punch_components.set(1, true);
      }
    // the unit load: 1 mm depth or 1 N. The tie's master is also the
    // punch's height for the edge contact; under displacement control its
    // dofs are all prescribed, so the tie only names the master.
    if (by_force || punch.edge_contact)
      ties.push_back({BoundaryId::top, 2, on_punch, Point<3>(0, 0, 0)});
    if (!by_force)
      punch_components.set(2, true);
    if (punch_components.n_selected_components() > 0)
      conditions.push_back({BoundaryId::top,
                            punch_components,
                            std::make_shared<Functions::ConstantFunction<3>>(
                              std::vector<double>{0., 0., by_force ? 0. : -1.}),
                            on_punch});
    const unsigned int punch_condition =
      by_force ? conditions.size() : conditions.size() - 1;

    std::unique_ptr<RigidPunchContact> edge_contact;
    if (punch.edge_contact)
      {
        TimerOutput::Scope t(timer, "setup");
        // the surface faces that wrapping around the edge can bring into
        // contact: up to a radius plus two edge radii beyond the rim
        const double reach = 2. * a + 2. * punch.edge_radius;
        edge_contact       = std::make_unique<RigidPunchContact>(
          PunchGeometry{Point<2>(0, 0), a, punch.edge_radius},
          punch.contact_penalty,
          parameters.layers.layer(0).youngs_modulus,
          reach,
          elasticity.get_dof_handler(),
          elasticity.get_mapping(),
          BoundaryId::top,
          [&elasticity]() { return elasticity.master_dof(0); });
        elasticity.attach(*edge_contact);
        pcout << "Edge contact: " << edge_contact->n_faces()
              << " surface faces within " << reach
              << " mm of the axis, edge radius " << punch.edge_radius << " mm"
              << std::endl;
      }
    {
      TimerOutput::Scope t(timer, "setup");
      elasticity.setup_system(conditions, ties);
    }
    const PointLocator locator(mesh.triangulation(), elasticity.get_mapping());
    const auto         profile_at =
      profile_points(punch,
                     std::min(parameters.mesh.patch_length_x,
                              parameters.mesh.patch_length_y));
    const auto                profile_locations = punch.profile_length > 0 ?
                                                    locator.locate(profile_at) :
                                                    std::vector<PointLocation>();
    const std::vector<double> loads             = punch.loads();
    std::vector<double>       depths, forces, times;
    std::vector<unsigned int> linear_iterations, newton_iterations, cuts;
    std::vector<std::vector<double>> profiles;
    std::vector<std::vector<double>> residual_histories;
    std::vector<double>              contact_areas;
    std::vector<double>              contact_penetrations;
    double                           unit_stiffness = 0, unit_force = 1;
    const auto write_fields = [&](const unsigned int step, const double time) {
      if (!run.write_fields)
        return;
      const std::string file =
        elasticity.write_vtu(output.directory(), "volume", step);
      output.add_pvd_record("volume", time, file);
      coupling.write(output, step, time);
    };

    if (!parameters.layers.nonlinear())
      {
        // Linear: one solve for the unit load (1 N or 1 mm), the steps by
        // scaling.
        Timer solve_timer(mpi_communicator, true);
        elasticity.assemble();
        if (by_force)
          elasticity.add_nodal_force(elasticity.master_dof(0), -1.);
        const LinearSolveReport report = elasticity.solve();
        {
          TimerOutput::Scope t(timer, "assembly");
          unit_force = -elasticity.reaction(punch_condition)[2];
        }
        const double unit_depth =
          by_force ? -elasticity.dof_value(elasticity.master_dof(0)) : 1.;
        unit_stiffness          = unit_force / unit_depth;
        const double solve_time = solve_timer.wall_time();
        pcout << "Unit load (" << (by_force ? "1 N" : "1 mm")
              << "): " << std::setprecision(6) << "force " << unit_force
              << " N, depth " << unit_depth << " mm";
        if (!run.test_mode)
          pcout << ", " << report.iterations << " CG iterations";
        pcout << std::endl;
        if (by_force && !run.test_mode)
          pcout << "Force balance of the tied punch: |reaction - 1 N| = "
                << std::abs(unit_force - 1.) << " N" << std::endl;
        const std::vector<double> unit_profile =
          vertical_displacements(profile_locations, elasticity);
        TimerOutput::Scope t(timer, "output");
        for (unsigned int step = 0; step < loads.size(); ++step)
          {
            // under force control the prescribed force, not the residual
            forces.push_back(by_force ? loads[step] :
                                        loads[step] * unit_stiffness);
            depths.push_back(by_force ? loads[step] * unit_depth : loads[step]);
            linear_iterations.push_back(step == 0 ? report.iterations : 0);
            newton_iterations.push_back(0);
            cuts.push_back(0);
            times.push_back(step == 0 ? solve_time : 0.);
            std::vector<double> profile(unit_profile);
            for (double &uz : profile)
              uz *= loads[step];
            profiles.push_back(profile);
            const double previous = step == 0 ? 1. : loads[step - 1];
            elasticity.scale_solution(loads[step] / previous);
            write_fields(step + 1, forces[step]);
            pcout << "Load step " << step + 1 << " of " << loads.size()
                  << ": force " << std::setprecision(6) << forces[step]
                  << " N, depth " << depths[step] << " mm" << std::endl;
          }
        elasticity.scale_solution(1. / loads.back());
        if (punch.section)
          write_section(parameters, locator, elasticity, loads.back(), output);
      }
    else
      {
        // Finite strain: Newton with adaptive load increments from one
        // target load to the next.
        NewtonSolver newton(elasticity,
                            parameters.newton,
                            pcout,
                            !run.test_mode);
        const auto   apply_load = [&](const double load)
          -> std::vector<std::pair<types::global_dof_index, double>> {
          if (by_force)
            {
              elasticity.apply_constraints_to_solution();
              return {{elasticity.master_dof(0), -load}};
            }
          // Newton's first update takes the punch to the new depth
          elasticity.set_dirichlet_scale(load);
          return {};
        };
        apply_load(0.);
        double position  = 0.;
        double increment = loads.front() / parameters.newton.initial_steps;
        for (unsigned int step = 0; step < loads.size(); ++step)
          {
            Timer                step_timer(mpi_communicator, true);
            const LoadPathReport report =
              newton.follow(position,
                            loads[step],
                            increment,
                            apply_load,
                            LoadDependence::right_hand_side);
            position = loads[step];
            double force;
            {
              TimerOutput::Scope t(timer, "assembly");
              force = by_force ? loads[step] :
                                 -elasticity.reaction(punch_condition)[2];
            }
            if (edge_contact)
              {
                const auto [area, penetration] =
                  edge_contact->contact_state(elasticity.solution());
                contact_areas.push_back(area);
                contact_penetrations.push_back(penetration);
                if (!run.test_mode)
                  pcout << "  edge contact: " << area
                        << " mm^2 of skin, largest penetration " << penetration
                        << " mm" << std::endl;
              }
            const double depth =
              by_force ? -elasticity.dof_value(elasticity.master_dof(0)) :
                         loads[step];
            forces.push_back(force);
            depths.push_back(depth);
            linear_iterations.push_back(report.linear_iterations);
            newton_iterations.push_back(report.newton_iterations);
            cuts.push_back(report.cuts);
            residual_histories.push_back(report.last_residuals);
            times.push_back(step_timer.wall_time());
            profiles.push_back(
              vertical_displacements(profile_locations, elasticity));
            {
              TimerOutput::Scope t(timer, "output");
              write_fields(step + 1, force);
            }
            pcout << "Load step " << step + 1 << " of " << loads.size()
                  << ": force " << std::setprecision(6) << force << " N, depth "
                  << depth << " mm";
            if (!run.test_mode)
              pcout << " (" << report.steps << " increments, " << report.cuts
                    << " cut, " << report.newton_iterations
                    << " Newton iterations, " << report.linear_iterations
                    << " CG iterations)";
            pcout << std::endl;
          }
        unit_stiffness = forces.front() / depths.front();
        if (punch.section)
          {
            TimerOutput::Scope t(timer, "output");
            write_section(parameters, locator, elasticity, 1., output);
          }
      }

    {
      TimerOutput::Scope t(timer, "output");
      if (punch.profile_length > 0)
        write_surface_profile(punch, profile_at, loads, profiles, output);
      std::ostringstream csv;
      csv << "step,force_N,depth_mm,newton_iterations,linear_iterations,"
             "load_cuts,wall_time_s\n"
          << std::setprecision(10);
      for (unsigned int k = 0; k < loads.size(); ++k)
        csv << k + 1 << ',' << forces[k] << ',' << depths[k] << ','
            << newton_iterations[k] << ',' << linear_iterations[k] << ','
            << cuts[k] << ',' << times[k] << '\n';
      output.write_text("force_displacement.csv", csv.str());
    }

    const Layer &top       = parameters.layers.layer(0);
    const double reference = half_space_stiffness(a,
                                                  top.youngs_modulus,
                                                  top.poisson_ratio,
                                                  punch.contact);
    pcout << "Stiffness: " << std::setprecision(6) << unit_stiffness
          << " N/mm (half-space reference for the top layer's material: "
          << reference << " N/mm)" << std::endl;

    nlohmann::ordered_json summary =
      scene.summary(elasticity.n_dofs(),
                    mesh.triangulation().n_global_active_cells());
    summary["embedded"]   = coupling.embedded_summary();
    const bool  nonlinear = parameters.layers.nonlinear();
    std::string models;
    for (unsigned int l = 0; l < parameters.layers.n_layers(); ++l)
      models += (l > 0 ? ", " : "") + parameters.layers.layer(l).name + ": " +
                to_string(parameters.layers.layer(l).model);
    summary["discretisation"] = {{"degree", parameters.elasticity.degree},
                                 {"formulation",
                                  to_string(parameters.elasticity.formulation)},
                                 {"material_model", models}};
    summary["solver"]         = solver_summary(
      linear_iterations, newton_iterations, cuts, times, residual_histories);
    if (!nonlinear)
      summary["solver"]["note"] =
        "linear elasticity: one solve for a unit load, the load steps by "
        "scaling";
    summary["control"] = by_force ? "force" : "displacement";
    summary["contact"] =
      punch.contact == PunchContact::bonded ? "bonded" : "frictionless";
    if (edge_contact)
      summary["edge_contact"] = {{"edge_radius_mm", punch.edge_radius},
                                 {"penalty_factor", punch.contact_penalty},
                                 {"area_mm2_per_step", contact_areas},
                                 {"max_penetration_mm_per_step",
                                  contact_penetrations}};
    summary["punch_radius_mm"]               = a;
    summary["force_N"]                       = forces;
    summary["depth_mm"]                      = depths;
    summary["stiffness_N_per_mm"]            = unit_stiffness;
    summary["half_space_stiffness_N_per_mm"] = reference;
    if (by_force && !nonlinear)
      summary["tie_force_balance_error_N"] = std::abs(unit_force - 1.);
    output.write_summary(summary);
    scene.print_wall_times();
    return {elasticity.n_dofs(), depths, forces, unit_stiffness, reference};
  }
} // namespace ssc
