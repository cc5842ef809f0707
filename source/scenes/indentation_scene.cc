#include <deal.II/base/function.h>
#include <deal.II/base/timer.h>

#include <ssc/background_mesh.h>
#include <ssc/embedding/point_locator.h>
#include <ssc/mechanics/linear_elastic_material.h>
#include <ssc/mechanics/microstructure_coupling.h>
#include <ssc/mechanics/volume_elasticity.h>
#include <ssc/output.h>
#include <ssc/scenes/indentation_scene.h>
#include <ssc/scenes/scene_run.h>

#include <cmath>
#include <iomanip>
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
    /// The lateral and bottom conditions common to every scene.
    std::vector<DirichletCondition>
    support_conditions(const SideCondition sides)
    {
      auto zero = std::make_shared<Functions::ZeroFunction<3>>(3);
      std::vector<DirichletCondition> conditions;
      conditions.push_back(
        {BoundaryId::bottom, ComponentMask(3, true), zero, {}});
      if (sides == SideCondition::free)
        return conditions;
      const bool fixed = sides == SideCondition::fixed;
      for (const types::boundary_id id : {BoundaryId::x_min,
                                          BoundaryId::x_max,
                                          BoundaryId::y_min,
                                          BoundaryId::y_max})
        {
          ComponentMask mask(3, fixed);
          mask.set(id <= BoundaryId::x_max ? 0 : 1, true);
          conditions.push_back({id, mask, zero, {}});
        }
      return conditions;
    }


    /// Writes surface_profile.csv: u_z along y = 0 at the surface, one
    /// column per load step (the unit-load response scaled).
    void
    write_surface_profile(const PunchParameters     &punch,
                          const double               patch_length,
                          const PointLocator        &locator,
                          const VolumeElasticity    &elasticity,
                          const std::vector<double> &loads,
                          RunOutput                 &output)
    {
      const double          L = std::min(punch.profile_length, patch_length);
      const unsigned int    n = punch.profile_points;
      std::vector<Point<3>> points;
      for (unsigned int i = 0; i < n; ++i)
        points.emplace_back(-L / 2 + L * i / (n - 1), 0., 0.);
      std::vector<Tensor<1, 3>>          u;
      std::vector<SymmetricTensor<2, 3>> strain;
      elasticity.evaluate_at(locator.locate(points), u, strain);
      std::ostringstream csv;
      csv << "x_mm";
      for (const double load : loads)
        csv << (punch.control == PunchControl::force ? ",uz_mm_at_F" :
                                                       ",uz_mm_at_depth")
            << load;
      csv << '\n' << std::setprecision(8);
      for (unsigned int i = 0; i < n; ++i)
        {
          csv << points[i][0];
          for (const double load : loads)
            csv << ',' << load * u[i][2];
          csv << '\n';
        }
      output.write_text("surface_profile.csv", csv.str());
    }


    /// Writes section.csv: displacement and von Mises stress on a grid of
    /// the plane y = 0 (the unit-load response times @p scale).
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
      std::vector<Tensor<1, 3>>          u;
      std::vector<SymmetricTensor<2, 3>> strain;
      elasticity.evaluate_at(locator.locate(points), u, strain);
      std::ostringstream csv;
      csv << "x_mm,z_mm,layer,ux_mm,uz_mm,von_mises_kPa\n"
          << std::setprecision(7);
      for (unsigned int k = 0; k < points.size(); ++k)
        {
          const unsigned int          l = layers.layer_at(points[k]);
          const LinearElasticMaterial material(layers.layer(l).youngs_modulus,
                                               layers.layer(l).poisson_ratio);
          const SymmetricTensor<2, 3> eps = scale * strain[k];
          csv << points[k][0] << ',' << points[k][2] << ',' << l << ','
              << scale * u[k][0] << ',' << scale * u[k][2] << ','
              << 1e3 * von_mises(material.stress(eps, trace(eps))) << '\n';
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

    BackgroundMesh mesh(parameters.layers, parameters.mesh, mpi_communicator);
    {
      TimerOutput::Scope t(timer, "mesh");
      mesh.build();
    }
    pcout << "Mesh: " << mesh.triangulation().n_global_active_cells()
          << " hexahedra over " << parameters.layers.n_layers() << " layers"
          << std::endl;

    VolumeElasticity elasticity(
      mesh, parameters.layers, parameters.elasticity, timer, pcout);
    {
      TimerOutput::Scope t(timer, "setup");
      elasticity.setup_dofs();
    }
    pcout << "Degrees of freedom: " << elasticity.n_dofs() << " (Q"
          << parameters.elasticity.degree << ", "
          << to_string(parameters.elasticity.formulation)
          << " formulation)" << std::endl;

    MicrostructureCoupling coupling(parameters, mesh, elasticity, timer, pcout);
    coupling.setup();

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
    // the unit load: 1 mm depth or 1 N
    if (by_force)
      ties.push_back({BoundaryId::top, 2, on_punch, Point<3>(0, 0, 0)});
    else
      punch_components.set(2, true);
    if (punch_components.n_selected_components() > 0)
      conditions.push_back({BoundaryId::top,
                            punch_components,
                            std::make_shared<Functions::ConstantFunction<3>>(
                              std::vector<double>{0., 0., by_force ? 0. : -1.}),
                            on_punch});
    const unsigned int punch_condition =
      by_force ? conditions.size() : conditions.size() - 1;

    Timer solve_timer(mpi_communicator, true);
    {
      TimerOutput::Scope t(timer, "setup");
      elasticity.setup_system(conditions, ties);
    }
    elasticity.assemble();
    if (by_force)
      elasticity.add_nodal_force(elasticity.master_dof(0), -1.);
    const LinearSolveReport report = elasticity.solve();
    // the force on the punch for the unit load, from the residual: under
    // force control it must equal 1 N (a check of the tie)
    double unit_force;
    {
      TimerOutput::Scope t(timer, "assembly");
      unit_force = -elasticity.reaction(punch_condition)[2];
    }
    const double unit_depth =
      by_force ? -elasticity.dof_value(elasticity.master_dof(0)) : 1.;
    const double unit_stiffness = unit_force / unit_depth;
    const double solve_time     = solve_timer.wall_time();
    pcout << "Unit load (" << (by_force ? "1 N" : "1 mm")
          << "): " << std::setprecision(6) << "force " << unit_force
          << " N, depth " << unit_depth << " mm";
    if (!run.test_mode)
      pcout << ", " << report.iterations << " CG iterations";
    pcout << std::endl;
    if (by_force && !run.test_mode)
      pcout << "Force balance of the tied punch: |reaction - 1 N| = "
            << std::abs(unit_force - 1.) << " N" << std::endl;

    // The load steps: the unit response scaled (linear elasticity).
    const std::vector<double> loads = punch.loads();
    std::vector<double>       depths, forces;
    for (const double load : loads)
      {
        // under force control the prescribed force, not the residual
        forces.push_back(by_force ? load : load * unit_stiffness);
        depths.push_back(by_force ? load * unit_depth : load);
      }
    const PointLocator locator(mesh.triangulation(), elasticity.get_mapping());
    {
      TimerOutput::Scope t(timer, "output");
      for (unsigned int step = 0; step < loads.size(); ++step)
        {
          const double previous = step == 0 ? 1. : loads[step - 1];
          elasticity.scale_solution(loads[step] / previous);
          if (run.write_fields)
            {
              const std::string file =
                elasticity.write_vtu(output.directory(), "volume", step + 1);
              output.add_pvd_record("volume", forces[step], file);
              coupling.write(output, step + 1, forces[step]);
            }
          pcout << "Load step " << step + 1 << " of " << loads.size()
                << ": force " << std::setprecision(6) << forces[step]
                << " N, depth " << depths[step] << " mm" << std::endl;
        }
      elasticity.scale_solution(1. / loads.back());
      if (punch.profile_length > 0)
        write_surface_profile(punch,
                              std::min(parameters.mesh.patch_length_x,
                                       parameters.mesh.patch_length_y),
                              locator,
                              elasticity,
                              loads,
                              output);
      if (punch.section)
        write_section(parameters, locator, elasticity, loads.back(), output);

      std::ostringstream csv;
      csv << "step,force_N,depth_mm,linear_iterations,wall_time_s\n"
          << std::setprecision(10);
      for (unsigned int k = 0; k < loads.size(); ++k)
        csv << k + 1 << ',' << forces[k] << ',' << depths[k] << ','
            << (k == 0 ? report.iterations : 0) << ','
            << (k == 0 ? solve_time : 0.) << '\n';
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
    summary["embedded"]       = coupling.embedded_summary();
    summary["discretisation"] = {{"degree", parameters.elasticity.degree},
                                 {"formulation",
                                  to_string(parameters.elasticity.formulation)},
                                 {"material_model", "linear"}};
    std::vector<unsigned int> per_step(loads.size(), 0);
    per_step[0]        = report.iterations;
    summary["solver"]  = {{"linear_iterations", report.iterations},
                          {"linear_iterations_per_step", per_step},
                          {"newton_iterations", 0},
                          {"linear_solves", 1},
                          {"note",
                           "linear elasticity: one solve for a unit load, "
                            "the load steps by scaling"}};
    summary["control"] = by_force ? "force" : "displacement";
    summary["contact"] =
      punch.contact == PunchContact::bonded ? "bonded" : "frictionless";
    summary["punch_radius_mm"]               = a;
    summary["force_N"]                       = forces;
    summary["depth_mm"]                      = depths;
    summary["stiffness_N_per_mm"]            = unit_stiffness;
    summary["half_space_stiffness_N_per_mm"] = reference;
    if (by_force)
      summary["tie_force_balance_error_N"] = std::abs(unit_force - 1.);
    output.write_summary(summary);
    scene.print_wall_times();
    return {elasticity.n_dofs(), depths, forces, unit_stiffness, reference};
  }
} // namespace ssc
