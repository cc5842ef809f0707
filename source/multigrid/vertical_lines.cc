#include <deal.II/base/quadrature.h>

#include <deal.II/fe/fe_values.h>

#include <map>

#include <ssc/multigrid/vertical_lines.h>

namespace ssc
{
  namespace
  {
    /// Orders lateral positions by x, then y, equal within a tolerance.
    struct LateralLess
    {
      double tolerance;

      bool
      operator()(const Point<2> &a, const Point<2> &b) const
      {
        if (std::abs(a[0] - b[0]) > tolerance)
          return a[0] < b[0];
        if (std::abs(a[1] - b[1]) > tolerance)
          return a[1] < b[1];
        return false;
      }
    };
  } // namespace


  DoFLines
  vertical_lines(const DoFHandler<3> &dof_handler,
                 const unsigned int   level,
                 const double         tolerance)
  {
    AssertThrow(tolerance > 0,
                ExcMessage("vertical_lines: the tolerance must be positive."));
    const bool active = (level == numbers::invalid_unsigned_int);
    const auto n_dofs =
      active ? dof_handler.n_dofs() : dof_handler.n_dofs(level);
    const FiniteElement<3> &fe = dof_handler.get_fe();
    const Quadrature<3>     support(fe.get_unit_support_points());
    FEValues<3>             fe_values(fe, support, update_quadrature_points);
    std::vector<types::global_dof_index>          indices(fe.n_dofs_per_cell());
    std::vector<Point<3>>                         point(n_dofs);
    std::vector<bool>                             seen(n_dofs, false);
    std::map<Point<2>, unsigned int, LateralLess> line_numbers(
      LateralLess{tolerance});

    const auto record = [&](const Triangulation<3>::cell_iterator &cell) {
      fe_values.reinit(cell); // geometry only: level cells are fine
      for (unsigned int i = 0; i < indices.size(); ++i)
        if (!seen[indices[i]])
          {
            point[indices[i]] = fe_values.quadrature_point(i);
            seen[indices[i]]  = true;
            line_numbers.emplace(Point<2>(point[indices[i]][0],
                                          point[indices[i]][1]),
                                 0);
          }
    };
    if (active)
      for (const auto &cell : dof_handler.active_cell_iterators())
        {
          cell->get_dof_indices(indices);
          record(cell);
        }
    else
      for (const auto &cell : dof_handler.mg_cell_iterators_on_level(level))
        {
          cell->get_mg_dof_indices(indices);
          record(cell);
        }

    unsigned int count = 0;
    for (auto &line : line_numbers)
      line.second = count++;
    DoFLines lines;
    lines.line.resize(n_dofs);
    lines.position.resize(n_dofs);
    for (types::global_dof_index i = 0; i < n_dofs; ++i)
      {
        lines.line[i]     = line_numbers.at(Point<2>(point[i][0], point[i][1]));
        lines.position[i] = point[i][2];
      }
    return lines;
  }
} // namespace ssc
