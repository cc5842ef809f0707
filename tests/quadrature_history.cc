// QuadratureHistory, the laws' history per quadrature point, on a
// distributed mesh of two materials (id 0 keeps 2 values a point, id 1
// none): only the cells of material 0 store history, zero at first; a step
// writes trial values, accept() commits them; the next step's trial values
// are thrown away by reject() (a cut load step), which restores the
// committed ones; a cell without history stores nothing. On two ranks each
// rank keeps its own cells and the sums over ranks are the same as on one.

#include <deal.II/distributed/tria.h>

#include <deal.II/grid/grid_generator.h>

#include <ssc/materials/quadrature_history.h>

#include "tests.h"

using namespace dealii;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();

  parallel::distributed::Triangulation<3> triangulation(MPI_COMM_WORLD);
  GridGenerator::subdivided_hyper_rectangle(triangulation,
                                            {4, 2, 2},
                                            Point<3>(),
                                            Point<3>(4, 2, 2));
  for (const auto &cell : triangulation.active_cell_iterators())
    cell->set_material_id(cell->center()[0] < 2 ? 0 : 1);

  const unsigned int     n_q_points = 8;
  ssc::QuadratureHistory history;
  history.initialize(triangulation, {2, 0}, n_q_points);

  // the sum of one copy over every stored value, and how many points keep
  // history, over all ranks
  const auto sum = [&](const bool trial) {
    double       total    = 0;
    unsigned int n_points = 0;
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned() && cell->material_id() == 0)
        for (unsigned int q = 0; q < n_q_points; ++q)
          {
            const auto values =
              trial ? ArrayView<const double>(history.trial(cell, q)) :
                      history.committed(cell, q);
            for (const double v : values)
              total += v;
            ++n_points;
          }
    deallog << (trial ? "trial" : "committed") << " sum "
            << Utilities::MPI::sum(total, MPI_COMM_WORLD) << " over "
            << Utilities::MPI::sum(n_points, MPI_COMM_WORLD) << " points"
            << std::endl;
  };

  // on any rank
  const auto empty_everywhere = [](const ssc::QuadratureHistory &h) {
    return Utilities::MPI::max(h.empty() ? 0u : 1u, MPI_COMM_WORLD) == 0;
  };
  deallog << "empty: " << (empty_everywhere(history) ? "yes" : "no")
          << std::endl;
  sum(false);

  // a step: every point's values 1 + its index within the cell
  const auto write = [&](const double offset) {
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned() && cell->material_id() == 0)
        for (unsigned int q = 0; q < n_q_points; ++q)
          for (double &v : history.trial(cell, q))
            v = offset + q;
  };
  write(1.);
  deallog << "step 1 solved" << std::endl;
  sum(true);
  sum(false);
  history.accept();
  deallog << "step 1 accepted" << std::endl;
  sum(false);

  write(100.);
  deallog << "step 2 solved" << std::endl;
  sum(true);
  history.reject();
  deallog << "step 2 rejected" << std::endl;
  sum(true);
  sum(false);

  ssc::QuadratureHistory elastic;
  elastic.initialize(triangulation, {0, 0}, n_q_points);
  deallog << "elastic laws only, empty: "
          << (empty_everywhere(elastic) ? "yes" : "no") << std::endl;
}
