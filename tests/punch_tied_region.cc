// Punch/Tied region = flat face: the bonded punch holds only the skin under
// the flat part of its face (r <= Radius - Edge radius), the skin under the
// rounded edge is carried by the edge contact alone. On the coarse forearm
// indentation at finite strain, with a 1.5 mm edge rounding on a 3 mm punch:
// the punch goes deeper at the same force than when it holds the whole face
// (a sharp rim at 3 mm), the skin beyond the tie is in contact with the
// rounding, which carries it: the punch goes clearly less deep than a
// punch of the flat face's radius alone (the skin under the rounding was
// once left out of the contact, and then it did not), and prescribing the
// depth found gives back the force (the contact on the rounding is counted
// on the punch under both controls).

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
                           {"Punch/Edge contact=true", "Punch/Edge radius=1.5"},
                           extra);
  };

  const auto whole = run({"Punch/Forces=0.2", "Run/Name=tied_whole_face"});
  const auto flat  = run({"Punch/Forces=0.2",
                          "Punch/Tied region=flat face",
                          "Run/Name=tied_flat_face"});
  MPI_Barrier(MPI_COMM_WORLD); // rank 0 writes the summary
  std::ifstream  file("results/tied_flat_face/summary.json");
  nlohmann::json summary = nlohmann::json::parse(file);
  const double   area    = summary["edge_contact"]["area_mm2_per_step"].back();
  // the flat face alone: a punch of radius R - rho whose edge is nearly
  // sharp, so that nothing but its face carries the skin
  const auto bare = run({"Punch/Forces=0.2",
                         "Punch/Radius=1.5",
                         "Punch/Edge radius=0.05",
                         "Run/Name=tied_bare_flat_face"});
  dealii::deallog << std::setprecision(3) << "0.2 N: depth "
                  << whole.depths.back() << " mm tied on the whole face, "
                  << flat.depths.back() << " mm on the flat face, "
                  << bare.depths.back()
                  << " mm for the flat face alone; deeper on the flat face: "
                  << (flat.depths.back() > whole.depths.back() ? "yes" : "no")
                  << "; skin in contact with the rounding (area above 1 "
                     "mm^2): "
                  << (area > 1. ? "yes" : "no")
                  << "; the rounding carries the skin (at least 10 % "
                     "shallower than the flat face alone): "
                  << (flat.depths.back() < 0.9 * bare.depths.back() ? "yes" :
                                                                      "no")
                  << std::endl;

  std::ostringstream depth;
  depth << std::setprecision(17) << flat.depths.back();
  const auto by_depth = run({"Punch/Control=displacement",
                             "Punch/Tied region=flat face",
                             "Punch/Depth=" + depth.str(),
                             "Punch/Load steps=2",
                             "Run/Name=tied_flat_face_depth"});
  dealii::deallog << "displacement control to that depth: relative "
                     "difference from 0.2 N below 1e-6: "
                  << (std::abs(by_depth.forces.back() / 0.2 - 1.) < 1e-6 ?
                        "yes" :
                        "no")
                  << std::endl;
}
