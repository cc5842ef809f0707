// Shared by the multigrid tests: a layered box with a thin middle layer and
// a mass plus Laplace matrix per component on it (positive definite without
// constraints), assembled on the active cells or on one level.

#ifndef ssc_tests_layered_box_h
#define ssc_tests_layered_box_h

#include <deal.II/base/quadrature_lib.h>

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>

#include <deal.II/fe/fe_values.h>

#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparse_matrix.h>

#include <deal.II/multigrid/mg_tools.h>

/// 2 x 2 lateral cells of 1 mm over layers of 1, 0.1 and 1 mm (material
/// ids 2, 1, 0 from the top), refined @p refinements times; the bottom
/// face has boundary id 4.
inline void
make_layered_box(dealii::Triangulation<3> &tria, const unsigned int refinements)
{
  dealii::GridGenerator::subdivided_hyper_rectangle(
    tria,
    {{1., 1.}, {1., 1.}, {1., 0.1, 1.}},
    dealii::Point<3>(0, 0, -2.1),
    dealii::Point<3>(2, 2, 0),
    /*colorize=*/true);
  for (const auto &cell : tria.active_cell_iterators())
    cell->set_material_id(cell->center()[2] < -1.1 ? 0 :
                          cell->center()[2] < -1.0 ? 1 :
                                                     2);
  tria.refine_global(refinements);
}


/// Mass plus (material id + 1)^2 times Laplace on the active cells (level
/// numbers::invalid_unsigned_int) or on one level, with the rows and
/// columns of @p constraints' DoFs decoupled.
inline void
make_layered_matrix(const dealii::DoFHandler<3>             &dof_handler,
                    const unsigned int                       level,
                    const dealii::AffineConstraints<double> &constraints,
                    dealii::SparsityPattern                 &sparsity,
                    dealii::SparseMatrix<double>            &matrix)
{
  using namespace dealii;
  const bool active = level == numbers::invalid_unsigned_int;
  const auto n      = active ? dof_handler.n_dofs() : dof_handler.n_dofs(level);
  DynamicSparsityPattern dsp(n);
  if (active)
    DoFTools::make_sparsity_pattern(dof_handler, dsp);
  else
    MGTools::make_sparsity_pattern(dof_handler, dsp, level);
  sparsity.copy_from(dsp);
  matrix.reinit(sparsity);
  const FiniteElement<3> &fe = dof_handler.get_fe();
  const QGauss<3>         quadrature(fe.degree + 1);
  const unsigned int      dofs_per_cell = fe.n_dofs_per_cell();
  FEValues<3>             fe_values(fe,
                        quadrature,
                        update_values | update_gradients | update_JxW_values);
  FullMatrix<double>      cell_matrix(dofs_per_cell, dofs_per_cell);
  std::vector<types::global_dof_index> indices(dofs_per_cell);
  const auto add_cell = [&](const Triangulation<3>::cell_iterator &cell) {
    fe_values.reinit(cell);
    const double stiffness =
      (cell->material_id() + 1.) * (cell->material_id() + 1.);
    cell_matrix = 0;
    for (unsigned int q = 0; q < quadrature.size(); ++q)
      for (unsigned int i = 0; i < dofs_per_cell; ++i)
        for (unsigned int j = 0; j < dofs_per_cell; ++j)
          if (fe.system_to_component_index(i).first ==
              fe.system_to_component_index(j).first)
            cell_matrix(i, j) +=
              (fe_values.shape_value(i, q) * fe_values.shape_value(j, q) +
               stiffness * fe_values.shape_grad(i, q) *
                 fe_values.shape_grad(j, q)) *
              fe_values.JxW(q);
    constraints.distribute_local_to_global(cell_matrix, indices, matrix);
  };
  if (active)
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        cell->get_dof_indices(indices);
        add_cell(cell);
      }
  else
    for (const auto &cell : dof_handler.mg_cell_iterators_on_level(level))
      {
        cell->get_mg_dof_indices(indices);
        add_cell(cell);
      }
}

#endif
