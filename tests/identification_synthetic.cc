// The in vivo identification on synthetic trials made by its own forward
// model: four trials (both probe faces, thin and thick fat) get the
// stiffness and layer strains of known moduli; Levenberg-Marquardt,
// started 30-60 % off, recovers every modulus to within 1 % (in fact to
// the tolerance) with a vanishing residual, and the predictions with the
// recovered moduli match the synthetic measurements. The forward model's
// homogeneity (all moduli times c: stiffness times c, strains over c),
// which the sensitivities rely on, holds to 1e-10. (The .mpirun=2 variant:
// the trials shared by two ranks, the same fit.)

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>

#include <cmath>
#include <fstream>
#include <iostream>

#include <ssc/identification/layer_moduli_fit.h>
#include <ssc/identification/probe_forward_model.h>
#include <ssc/scenes/parameters.h>

#include "tests.h"

using namespace dealii;

namespace
{
  /// A coarse, fast forward model (Q2 mixed on the quarter).
  const char *forward_prm = R"(
subsection Run
  set Scene = identification
  set Name  = synthetic
end
subsection Identification
  set Data file     = unused.csv
  set Fitted moduli = skin, fat, muscle
  set Fitted data   = stiffness, skin strain, fat strain, muscle strain
  set Tolerance     = 1e-10
end
subsection Layer stack
  set Layers = skin, fat, muscle
  subsection skin
    set Kind            = skin
    set Thickness       = 1.5
    set Young's modulus = 0.02
    set Poisson's ratio = 0.49
    set Material model  = linear
  end
  subsection fat
    set Kind            = SAT
    set Thickness       = 4
    set Young's modulus = 0.01
    set Poisson's ratio = 0.49
    set Material model  = linear
  end
  subsection muscle
    set Kind            = deep
    set Thickness       = 17
    set Young's modulus = 0.01
    set Poisson's ratio = 0.49
    set Material model  = linear
    set Cells across    = 2
  end
end
subsection Mesh
  set Patch length x      = 100
  set Patch length y      = 60
  set Cell size           = 10
  set Core half width     = 22.5
  set Core half width y   = 4
  set Core edge cell size = 4
  set Grading ratio       = 2
  set Symmetry            = quarter
end
subsection Elasticity
  set Degree      = 2
  set Formulation = mixed
  subsection Linear solver
    set Preconditioner = cholesky
  end
end
subsection Punch
  set Shape   = rectangle
  set Control = force
end
)";

  ssc::IndentationTrial
  trial(const unsigned int line,
        const double       skin,
        const double       fat,
        const double       muscle,
        const double       area)
  {
    ssc::IndentationTrial t;
    t.line             = line;
    t.subject          = std::to_string(line);
    t.site             = "LA_A";
    t.skin_thickness   = skin;
    t.fat_thickness    = fat;
    t.muscle_thickness = muscle;
    t.probe_area       = area;
    t.max_force        = 4;
    return t;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
    std::ofstream("forward.prm") << forward_prm;
  MPI_Barrier(MPI_COMM_WORLD);

  ssc::Parameters parameters;
  parameters.read("forward.prm", {});
  ConditionalOStream silent(std::cout, false);
  TimerOutput        timer(silent, TimerOutput::never, TimerOutput::wall_times);
  const ssc::ProbeForwardModel model(parameters, timer);

  const std::array<double, 3>        truth  = {{0.015, 0.03, 0.009}};
  std::vector<ssc::IndentationTrial> trials = {trial(2, 1.6, 3.8, 16.8, 360),
                                               trial(3, 1.1, 9.5, 21.0, 360),
                                               trial(4, 2.0, 2.2, 12.5, 675),
                                               trial(5, 1.3, 6.0, 30.0, 675)};
  for (auto &t : trials)
    {
      const ssc::ProbeResponse r = model.solve(t, truth);
      t.surface_stiffness        = r.stiffness;
      t.skin_strain              = t.max_force * r.strains_per_newton[0];
      t.fat_strain               = t.max_force * r.strains_per_newton[1];
      t.muscle_strain            = t.max_force * r.strains_per_newton[2];
      deallog << "trial " << t.line << ": stiffness " << t.surface_stiffness
              << " N/mm, strains " << t.skin_strain << ' ' << t.fat_strain
              << ' ' << t.muscle_strain << std::endl;
    }

  // homogeneity of degree one in the moduli
  {
    const ssc::ProbeResponse r = model.solve(trials[1], truth);
    const ssc::ProbeResponse s =
      model.solve(trials[1],
                  {{2.5 * truth[0], 2.5 * truth[1], 2.5 * truth[2]}});
    double largest = std::abs(s.stiffness / (2.5 * r.stiffness) - 1);
    for (unsigned int i = 0; i < 3; ++i)
      largest = std::max(
        largest,
        std::abs(2.5 * s.strains_per_newton[i] / r.strains_per_newton[i] - 1));
    deallog << "homogeneous of degree one to 1e-10: "
            << (largest < 1e-10 ? "yes" : "no") << std::endl;
  }

  const ssc::LayerModuliFit fitter(model,
                                   parameters.identification,
                                   MPI_COMM_WORLD);
  const ssc::ModuliFit      fit =
    fitter.fit(trials,
               {{1.6 * truth[0], 0.5 * truth[1], 1.4 * truth[2]}},
               silent);
  deallog << "converged: " << (fit.converged ? "yes" : "no") << " ("
          << fit.stopping_reason << ")" << std::endl;
  for (unsigned int l = 0; l < 3; ++l)
    {
      const double error = std::abs(fit.moduli[l] / truth[l] - 1);
      deallog << ssc::trial_layer_names[l] << " modulus recovered within 1 %: "
              << (error < 0.01 ? "yes" : "no")
              << ", within 1e-6: " << (error < 1e-6 ? "yes" : "no")
              << std::endl;
    }
  deallog << "rms residual below 1e-8: "
          << (fit.rms_residual < 1e-8 ? "yes" : "no") << std::endl;

  const auto errors =
    ssc::prediction_errors(fitter.predict(trials, fit.moduli), trials);
  deallog << "median prediction errors below 1e-4 %: "
          << (errors.stiffness_pct < 1e-4 &&
                  errors.pooled_layer_strain_pct < 1e-4 ?
                "yes" :
                "no")
          << std::endl;
}
