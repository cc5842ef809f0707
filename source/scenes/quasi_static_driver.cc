#include <deal.II/base/timer.h>

#include <numeric>

#include <ssc/scenes/quasi_static_driver.h>

namespace ssc
{
  QuasiStaticDriver::QuasiStaticDriver(ElasticSystem          &system,
                                       const NewtonParameters &parameters,
                                       ConditionalOStream     &pcout,
                                       const bool              verbose)
    : system(system)
    , problem(system)
    , newton(problem, parameters, pcout, verbose)
  {}


  bool
  QuasiStaticDriver::linear() const
  {
    return !system.materials().any_finite_strain();
  }


  void
  QuasiStaticDriver::run(const std::vector<double>         &targets,
                         const std::function<void(double)> &apply_load,
                         const double                       first_increment,
                         const LoadDependence               dependence,
                         const std::function<void(unsigned int)> &on_step)
  {
    const MPI_Comm communicator =
      system.field().dof_handler().get_triangulation().get_communicator();
    steps.clear();
    if (linear())
      {
        // one solve for the unit load, every target by scaling
        Timer timer(communicator, true);
        apply_load(1.);
        const LinearSolveReport report = solve_linear(system);
        double                  scale  = 1.;
        for (unsigned int k = 0; k < targets.size(); ++k)
          {
            TrilinosWrappers::MPI::Vector u = system.field().owned_solution();
            u *= targets[k] / scale;
            system.field().set_solution(u);
            scale = targets[k];
            // the loads that belong to the scaled state
            apply_load(targets[k]);
            StepStatistics step;
            if (k == 0)
              {
                step.linear_iterations = report.iterations;
                step.wall_time         = timer.wall_time();
              }
            steps.push_back(step);
            on_step(k);
          }
        return;
      }

    LoadStepper stepper(newton);
    apply_load(0.);
    system.constraints().apply(system.field());
    double position = 0., increment = first_increment;
    for (unsigned int k = 0; k < targets.size(); ++k)
      {
        Timer                timer(communicator, true);
        const LoadPathReport report = stepper.follow(
          position, targets[k], increment, apply_load, dependence);
        position = targets[k];
        StepStatistics step;
        step.linear_iterations = report.linear_iterations;
        step.newton_iterations = report.newton_iterations;
        step.increments        = report.steps;
        step.cuts              = report.cuts;
        step.final_residuals   = report.last_residuals;
        step.wall_time         = timer.wall_time();
        steps.push_back(step);
        on_step(k);
      }
  }


  nlohmann::ordered_json
  QuasiStaticDriver::summary() const
  {
    std::vector<unsigned int>        cg, newton, cuts;
    std::vector<double>              times;
    std::vector<std::vector<double>> residuals;
    for (const StepStatistics &step : steps)
      {
        cg.push_back(step.linear_iterations);
        newton.push_back(step.newton_iterations);
        cuts.push_back(step.cuts);
        times.push_back(step.wall_time);
        residuals.push_back(step.final_residuals);
      }
    const auto total = [](const std::vector<unsigned int> &counts) {
      return std::accumulate(counts.begin(), counts.end(), 0u);
    };
    nlohmann::ordered_json solver        = {{"linear_iterations", total(cg)},
                                            {"linear_iterations_per_step", cg},
                                            {"newton_iterations", total(newton)},
                                            {"newton_iterations_per_step", newton},
                                            {"load_cuts_per_step", cuts},
                                            {"wall_time_per_step", times}};
    const LinearSolver    &linear_solver = system.tangent_system().solver();
    solver["preconditioner"]             = linear_solver.preconditioner_name();
    if (linear_solver.factorizations() > 0)
      solver["cholesky_factorizations"] = linear_solver.factorizations();
    if (linear_solver.indefinite_factorizations() > 0)
      solver["indefinite_factorizations"] =
        linear_solver.indefinite_factorizations();
    if (!linear())
      solver["final_residuals_per_step"] = residuals;
    else
      solver["note"] = "linear elasticity: one solve for a unit load, the "
                       "load steps by scaling";
    return solver;
  }
} // namespace ssc
