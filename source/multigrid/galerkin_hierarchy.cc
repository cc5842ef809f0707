#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <tuple>

#include <ssc/multigrid/galerkin_hierarchy.h>

namespace ssc
{
  namespace
  {
    /// The prolongation from level @p level - 1 to @p level, without the
    /// Dirichlet DoFs of either level.
    void
    make_prolongation(const DoFHandler<3>     &dof_handler,
                      const MGConstrainedDoFs &constrained_dofs,
                      const unsigned int       level,
                      SparsityPattern         &sparsity,
                      SparseMatrix<double>    &prolongation)
    {
      const FiniteElement<3> &fe = dof_handler.get_fe();
      const IndexSet         &fine_boundary =
        constrained_dofs.get_boundary_indices(level);
      const IndexSet &coarse_boundary =
        constrained_dofs.get_boundary_indices(level - 1);
      std::vector<types::global_dof_index> parent_dofs(fe.n_dofs_per_cell()),
        child_dofs(fe.n_dofs_per_cell());
      DynamicSparsityPattern dsp(dof_handler.n_dofs(level),
                                 dof_handler.n_dofs(level - 1));
      std::vector<
        std::tuple<types::global_dof_index, types::global_dof_index, double>>
        entries;
      for (const auto &cell : dof_handler.mg_cell_iterators_on_level(level - 1))
        if (cell->has_children())
          {
            cell->get_mg_dof_indices(parent_dofs);
            for (unsigned int c = 0; c < cell->n_children(); ++c)
              {
                cell->child(c)->get_mg_dof_indices(child_dofs);
                const FullMatrix<double> &child_prolongation =
                  fe.get_prolongation_matrix(c, cell->refinement_case());
                for (unsigned int i = 0; i < child_dofs.size(); ++i)
                  for (unsigned int j = 0; j < parent_dofs.size(); ++j)
                    if (child_prolongation(i, j) != 0 &&
                        !fine_boundary.is_element(child_dofs[i]) &&
                        !coarse_boundary.is_element(parent_dofs[j]))
                      {
                        dsp.add(child_dofs[i], parent_dofs[j]);
                        entries.emplace_back(child_dofs[i],
                                             parent_dofs[j],
                                             child_prolongation(i, j));
                      }
              }
          }
      sparsity.copy_from(dsp);
      prolongation.reinit(sparsity);
      // a fine DoF shared by several children gets the same value from each
      for (const auto &[i, j, value] : entries)
        prolongation.set(i, j, value);
    }
  } // namespace


  void
  make_galerkin_hierarchy(const DoFHandler<3>                 &dof_handler,
                          const MGConstrainedDoFs             &constrained_dofs,
                          MGLevelObject<SparsityPattern>      &sparsity,
                          MGLevelObject<SparseMatrix<double>> &matrices)
  {
    AssertThrow(matrices.min_level() == 0 && sparsity.min_level() == 0 &&
                  matrices.max_level() == sparsity.max_level() &&
                  matrices.max_level() + 1 ==
                    dof_handler.get_triangulation().n_global_levels(),
                ExcMessage("make_galerkin_hierarchy: one matrix and one "
                           "sparsity pattern per level of the mesh are "
                           "needed."));
    for (unsigned int level = matrices.max_level(); level > 0; --level)
      {
        SparsityPattern      prolongation_sparsity, product_sparsity;
        SparseMatrix<double> prolongation, product;
        make_prolongation(dof_handler,
                          constrained_dofs,
                          level,
                          prolongation_sparsity,
                          prolongation);
        // A P, then P^T (A P): both patterns are rebuilt by the products
        product.reinit(product_sparsity);
        matrices[level].mmult(product, prolongation);
        matrices[level - 1].clear();
        matrices[level - 1].reinit(sparsity[level - 1]);
        prolongation.Tmmult(matrices[level - 1], product);
        for (const auto dof : constrained_dofs.get_boundary_indices(level - 1))
          matrices[level - 1].set(dof, dof, 1.);
      }
  }
} // namespace ssc
