#ifndef ssc_multigrid_galerkin_hierarchy_h
#define ssc_multigrid_galerkin_hierarchy_h

#include <deal.II/base/mg_level_object.h>

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>

#include <deal.II/multigrid/mg_constrained_dofs.h>

#include <functional>

namespace ssc
{
  using namespace dealii;

  /**
   * The finite element's prolongation from level @p level - 1 to @p level
   * of a nested mesh, entry by entry: visit(fine, coarse, value) for each
   * nonzero entry of the rows of this process's cells on @p level (an
   * entry shared by several cells comes once per cell, with the same
   * value). The coarse DoFs have their level numbers; the fine ones too,
   * or, with @p fine_active_dofs, their numbers among the active DoFs of
   * that DoFHandler on the same mesh (for the finest level of uniform
   * refinements, whose cells are the active ones).
   *
   * Why here: the level matrices of the serial hierarchy below and of the
   * distributed V-cycle are both products with this one prolongation.
   */
  void
  for_each_prolongation_entry(
    const DoFHandler<3> &dof_handler,
    const unsigned int   level,
    const DoFHandler<3> *fine_active_dofs,
    const std::function<
      void(types::global_dof_index, types::global_dof_index, double)> &visit);

  /**
   * The matrices of the levels below the finest as Galerkin products
   * A_{l-1} = P^T A_l P, from the finest level's matrix down, with P the
   * finite element's prolongation from level l-1 to level l.
   *
   * Why: ssc's tangent holds more than the cells' kernels (embedded septa
   * and ligaments, contact and friction). A coarse level assembled from
   * the cells would miss them; the Galerkin product carries every term of
   * the fine matrix down, and for terms that a coarse cell resolves (a
   * modulus constant on it, exact quadrature) it equals the assembled
   * coarse matrix.
   *
   * The Dirichlet DoFs of @p constrained_dofs are kept out of P (their
   * fine rows and coarse columns are zero), so a coarse correction never
   * moves them; their rows of the coarse matrices are the identity, as
   * those of an assembled level matrix with the constraints applied.
   *
   * On entry @p matrices[finest] holds the finest level's matrix (level
   * numbering); the coarser entries and their @p sparsity are rebuilt.
   * Serial (dealii::SparseMatrix).
   */
  void
  make_galerkin_hierarchy(const DoFHandler<3>                 &dof_handler,
                          const MGConstrainedDoFs             &constrained_dofs,
                          MGLevelObject<SparsityPattern>      &sparsity,
                          MGLevelObject<SparseMatrix<double>> &matrices);
} // namespace ssc

#endif
