#ifndef ssc_tests_h
#define ssc_tests_h

// Minimal deal.II-style test harness: initlog() sends deallog to the file
// "output" that the test driver compares with NAME.output (numdiff).

#include <deal.II/base/logstream.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <fstream>
#include <iomanip>

inline std::ofstream &
deallogfile()
{
  static std::ofstream file;
  return file;
}

/// Attaches deallog to "output" (rank 0 only writes anything).
inline void
initlog()
{
  if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
    deallogfile().open("output");
  else
    deallogfile().open("/dev/null");
  dealii::deallog.attach(deallogfile(), false);
  dealii::deallog.depth_console(0);
  dealii::deallog << std::setprecision(6);
}

#endif
