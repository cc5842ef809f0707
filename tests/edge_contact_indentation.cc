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
// parallel assembly, not that case.)

#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>
#include <iomanip>
#include <sstream>

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
  const auto by_force = run({"Punch/Control=force",
                             "Punch/Forces=0.35, 0.5",
                             "Run/Name=edge_contact_force"});
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
