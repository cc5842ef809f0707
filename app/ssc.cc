// The ssc executable: the command line only; everything else is in libssc.

#include <deal.II/base/mpi.h>

#include <iostream>

#include <ssc/application.h>

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const std::vector<std::string>           arguments(argv + 1, argv + argc);
  return ssc::run_command_line(arguments, MPI_COMM_WORLD, std::cout, std::cerr);
}
