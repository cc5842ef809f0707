#include <deal.II/base/quadrature.h>

#include <deal.II/fe/fe_values.h>

#include <algorithm>
#include <map>

#include <ssc/multigrid/vertical_lines.h>

namespace ssc
{
  bool
  LateralLess::operator()(const Point<2> &a, const Point<2> &b) const
  {
    if (std::abs(a[0] - b[0]) > tolerance)
      return a[0] < b[0];
    if (std::abs(a[1] - b[1]) > tolerance)
      return a[1] < b[1];
    return false;
  }


  DoFLines
  vertical_lines(const DoFHandler<3>   &dof_handler,
                 const unsigned int     level,
                 const double           tolerance,
                 std::vector<Point<2>> *lateral)
  {
    AssertThrow(tolerance > 0,
                ExcMessage("vertical_lines: the tolerance must be positive."));
    const bool              active = (level == numbers::invalid_unsigned_int);
    const IndexSet         &owned  = active ? dof_handler.locally_owned_dofs() :
                                              dof_handler.locally_owned_mg_dofs(level);
    const auto              n_dofs = owned.n_elements();
    const FiniteElement<3> &fe     = dof_handler.get_fe();
    const Quadrature<3>     support(fe.get_unit_support_points());
    FEValues<3>             fe_values(fe, support, update_quadrature_points);
    std::vector<types::global_dof_index>          indices(fe.n_dofs_per_cell());
    std::vector<Point<3>>                         point(n_dofs);
    std::vector<bool>                             seen(n_dofs, false);
    std::map<Point<2>, unsigned int, LateralLess> line_numbers(
      LateralLess{tolerance});

    // every DoF of this process is on one of its cells
    const auto record = [&](const Triangulation<3>::cell_iterator &cell) {
      fe_values.reinit(cell); // geometry only: level cells are fine
      for (unsigned int i = 0; i < indices.size(); ++i)
        if (owned.is_element(indices[i]))
          {
            const auto local = owned.index_within_set(indices[i]);
            if (seen[local])
              continue;
            point[local] = fe_values.quadrature_point(i);
            seen[local]  = true;
            line_numbers.emplace(Point<2>(point[local][0], point[local][1]), 0);
          }
    };
    if (active)
      for (const auto &cell : dof_handler.active_cell_iterators())
        {
          if (!cell->is_locally_owned())
            continue;
          cell->get_dof_indices(indices);
          record(cell);
        }
    else
      for (const auto &cell : dof_handler.mg_cell_iterators_on_level(level))
        {
          if (!cell->is_locally_owned_on_level())
            continue;
          cell->get_mg_dof_indices(indices);
          record(cell);
        }
    AssertThrow(std::find(seen.begin(), seen.end(), false) == seen.end(),
                ExcInternalError());

    unsigned int count = 0;
    if (lateral != nullptr)
      lateral->clear();
    for (auto &line : line_numbers)
      {
        line.second = count++;
        if (lateral != nullptr)
          lateral->push_back(line.first);
      }
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
