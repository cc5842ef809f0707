// The frictionless punch at finite strain with the edge contact
// (Punch/Edge contact): on the coarse forearm indentation (neo-Hookean
// layers, mean dilatation, tension-field septa, tension-only ligaments)
// force control goes past 0.336 N, where Newton stalled without the
// contact because the skin passed through the punch's edge, to 0.5 N; the
// skin is then in contact with the rounded edge; and prescribing the depth
// found for 0.5 N gives back 0.5 N, so the contact forces on the punch are
// counted the same way under force and under displacement control; the
// same on 2 ranks. (On the forearm mesh one of 2 ranks saw no face of the
// punch's master dof and left it unconstrained under displacement
// control; on this mesh both ranks see it, so this variant checks the
// parallel assembly, not that case.) Under force control every increment
// starts no further from equilibrium than its converged state, whose
// residual is the force increment: the secant predictor, which overshoots
// this stiffening response, is dropped where it does not lower the
// residual (log.txt: each "Newton: residual" line against the increment
// of the "load" line that ends it).

#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <string>

#include "indentation_run.h"
#include "tests.h"

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  const auto run = [](const std::vector<std::string> &extra) {
    return run_indentation("indentation_neo_hookean.prm",
                           {"Punch/Contact=frictionless",
                            "Punch/Edge contact=true"},
                           extra);
  };
  // not in test mode: log.txt gets Newton's progress
  const auto by_force = run({"Punch/Control=force",
                             "Punch/Forces=0.35, 0.5",
                             "Run/Name=edge_contact_force",
                             "Run/Test mode=false"});
  // rank 0 writes the summary
  MPI_Barrier(MPI_COMM_WORLD);
  std::ifstream  file("results/edge_contact_force/summary.json");
  nlohmann::json summary = nlohmann::json::parse(file);
  const double   area    = summary["edge_contact"]["area_mm2_per_step"].back();
  dealii::deallog << "force control: 0.5 N at depth " << std::setprecision(4)
                  << by_force.depths.back()
                  << " mm; skin in contact with the edge (area above 1 "
                     "mm^2): "
                  << (area > 1. ? "yes" : "no") << std::endl;

  // "    Newton: residual R" opens an increment, "  load L: N Newton
  // iterations" closes a converged one, "  load increment to ..." a cut one
  std::ifstream log("results/edge_contact_force/log.txt");
  std::string   line;
  double        start = -1, load = 0;
  unsigned int  increments = 0, worse = 0;
  while (std::getline(log, line))
    if (line.find("Newton: residual") != std::string::npos)
      start = std::stod(line.substr(line.rfind(' ') + 1));
    else if (line.rfind("  load increment", 0) == 0)
      start = -1;
    else if (line.rfind("  load ", 0) == 0 && start >= 0)
      {
        const double next = std::stod(line.substr(7));
        // both printed to 4-6 digits
        worse += start > (next - load) * (1. + 1e-3);
        ++increments;
        load  = next;
        start = -1;
      }
  dealii::deallog << "force control: " << increments
                  << " increments, each starting with a residual at most its "
                     "force increment: "
                  << (increments > 2 && worse == 0 ? "yes" : "no") << std::endl;

  std::ostringstream depth;
  depth << std::setprecision(17) << by_force.depths.back();
  const auto by_depth = run({"Punch/Control=displacement",
                             "Punch/Depth=" + depth.str(),
                             "Punch/Load steps=2",
                             "Run/Name=edge_contact_depth"});
  dealii::deallog << "displacement control to that depth: relative "
                     "difference from 0.5 N below 1e-6: "
                  << (std::abs(by_depth.forces.back() / 0.5 - 1.) < 1e-6 ?
                        "yes" :
                        "no")
                  << std::endl;
}
