// The ssc executable: the command line only; everything else is in libssc.

#include <deal.II/base/mpi.h>

#include <iostream>

#include <ssc/application.h>

int
main(int argc, char **argv)
{
  // the cores not taken by MPI ranks run the cell loops' threads: one rank
  // (the direct factors need one) assembles on every core
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv);
  const std::vector<std::string>           arguments(argv + 1, argv + argc);
  return ssc::run_command_line(arguments, MPI_COMM_WORLD, std::cout, std::cerr);
}
