// DiskFittingMap: the square |p|_inf = a goes onto the circle r = a, points
// beyond 2a stay put, and inverse(forward(p)) = p everywhere.

#include <cmath>

#include <ssc/mesh/disk_fitting_map.h>

#include "tests.h"

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  const double              a = 2.5;
  const ssc::DiskFittingMap map(a);

  double square_to_circle = 0, far_field = 0, round_trip = 0;
  for (unsigned int i = 0; i <= 200; ++i)
    {
      const double s = -a + 2 * a * i / 200.;
      for (const dealii::Point<2> &p : {dealii::Point<2>(s, a),
                                        dealii::Point<2>(a, s),
                                        dealii::Point<2>(s, -a),
                                        dealii::Point<2>(-a, s)})
        square_to_circle =
          std::max(square_to_circle, std::abs(map.forward(p).norm() - a));
      const dealii::Point<2> far(3 * s, 2.01 * a);
      far_field = std::max(far_field, far.distance(map.forward(far)));
      for (unsigned int j = 0; j <= 50; ++j)
        {
          const dealii::Point<2> p(3 * s, -3 * a + 6 * a * j / 50.);
          round_trip =
            std::max(round_trip, p.distance(map.inverse(map.forward(p))));
        }
    }
  dealii::deallog << "square onto circle: " << (square_to_circle < 1e-12)
                  << std::endl
                  << "identity beyond 2a: " << (far_field < 1e-12) << std::endl
                  << "inverse(forward(p)) = p: " << (round_trip < 1e-10)
                  << std::endl
                  << "centre fixed: " << map.forward(dealii::Point<2>()).norm()
                  << std::endl
                  << "(1.25, 0) -> " << map.forward(dealii::Point<2>(1.25, 0))
                  << ", (2.5, 2.5) -> "
                  << map.forward(dealii::Point<2>(2.5, 2.5)) << std::endl;
}
