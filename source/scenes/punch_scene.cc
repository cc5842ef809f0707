#include <deal.II/base/function.h>
#include <deal.II/base/timer.h>

#include <ssc/background_mesh.h>
#include <ssc/mechanics/microstructure_coupling.h>
#include <ssc/mechanics/volume_elasticity.h>
#include <ssc/output.h>
#include <ssc/scenes/punch_scene.h>
#include <ssc/scenes/scene_run.h>

#include <cmath>
#include <iomanip>
#include <sstream>

namespace ssc
{
  PunchScene::PunchScene(const Parameters &parameters,
                         const MPI_Comm    mpi_communicator)
    : parameters(parameters)
    , mpi_communicator(mpi_communicator)
  {}


  double
  PunchScene::half_space_stiffness(const double       a,
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
  } // namespace


  PunchResult
  PunchScene::run()
  {
    const RunParameters &run = parameters.run;
    SceneRun             scene(parameters, mpi_communicator, "punch");
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
          << (parameters.elasticity.formulation == Formulation::mixed ?
                "mixed" :
                "displacement")
          << " formulation)" << std::endl;

    MicrostructureCoupling coupling(parameters, mesh, elasticity, timer, pcout);
    coupling.setup();

    const PunchParameters &punch    = parameters.punch;
    const double           a        = punch.radius;
    const auto             on_punch = [a](const Point<3> &p) {
      return std::hypot(p[0], p[1]) <= a * (1. + 1e-10);
    };
    ComponentMask punch_components(3, punch.contact == PunchContact::bonded);
    punch_components.set(2, true);

    std::vector<double>       depths, forces, times;
    std::vector<unsigned int> iterations;
    for (unsigned int step = 1; step <= punch.load_steps; ++step)
      {
        Timer        step_timer(mpi_communicator, true);
        const double depth = punch.depth * step / punch.load_steps;
        std::vector<DirichletCondition> conditions =
          support_conditions(parameters.elasticity.sides);
        conditions.push_back({BoundaryId::top,
                              punch_components,
                              std::make_shared<Functions::ConstantFunction<3>>(
                                std::vector<double>{0., 0., -depth}),
                              on_punch});
        {
          TimerOutput::Scope t(timer, "setup");
          elasticity.setup_system(conditions);
        }
        elasticity.assemble();
        const LinearSolveReport report = elasticity.solve();
        double                  force;
        {
          TimerOutput::Scope t(timer, "assembly");
          force = -elasticity.reaction(conditions.size() - 1)[2];
        }
        {
          TimerOutput::Scope t(timer, "output");
          const std::string  file =
            elasticity.write_vtu(output.directory(), "volume", step);
          output.add_pvd_record("volume", depth, file);
          coupling.write(output, step, depth);
        }
        depths.push_back(depth);
        forces.push_back(force);
        iterations.push_back(report.iterations);
        times.push_back(step_timer.wall_time());

        pcout << "Load step " << step << " of " << punch.load_steps
              << ": depth " << depth << " mm, force " << std::setprecision(6)
              << force << " N";
        if (!run.test_mode)
          pcout << ", " << report.iterations << " CG iterations";
        pcout << std::endl;
      }

    const double stiffness = forces.front() / depths.front();
    const Layer &top       = parameters.layers.layer(0);
    const double reference = half_space_stiffness(a,
                                                  top.youngs_modulus,
                                                  top.poisson_ratio,
                                                  punch.contact);
    pcout << "Stiffness: " << std::setprecision(6) << stiffness
          << " N/mm (half-space reference for the top layer's material: "
          << reference << " N/mm)" << std::endl;

    {
      TimerOutput::Scope t(timer, "output");
      std::ostringstream csv;
      csv << "step,depth_mm,force_N,linear_iterations,wall_time_s\n"
          << std::setprecision(10);
      for (unsigned int k = 0; k < depths.size(); ++k)
        csv << k + 1 << ',' << depths[k] << ',' << forces[k] << ','
            << iterations[k] << ',' << times[k] << '\n';
      output.write_text("force_displacement.csv", csv.str());
    }

    nlohmann::ordered_json summary =
      scene.summary(elasticity.n_dofs(),
                    mesh.triangulation().n_global_active_cells());
    summary["embedded"]           = coupling.embedded_summary();
    summary["discretisation"]     = {{"degree", parameters.elasticity.degree},
                                     {"formulation",
                                  parameters.elasticity.formulation ==
                                      Formulation::mixed ?
                                        "mixed" :
                                        "displacement"},
                                     {"material_model", "linear"}};
    unsigned int total_iterations = 0;
    for (const unsigned int i : iterations)
      total_iterations += i;
    summary["solver"] = {{"linear_iterations", total_iterations},
                         {"linear_iterations_per_step", iterations},
                         {"newton_iterations", 0}};
    summary["contact"] =
      punch.contact == PunchContact::bonded ? "bonded" : "frictionless";
    summary["punch_radius_mm"]               = a;
    summary["force_N"]                       = forces;
    summary["depth_mm"]                      = depths;
    summary["stiffness_N_per_mm"]            = stiffness;
    summary["half_space_stiffness_N_per_mm"] = reference;
    output.write_summary(summary);
    scene.print_wall_times();
    return {elasticity.n_dofs(), depths, forces, stiffness, reference};
  }
} // namespace ssc
