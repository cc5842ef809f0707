#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <string>
#include <tuple>

#include <ssc/multigrid/galerkin_hierarchy.h>

namespace ssc
{
  void
  for_each_prolongation_entry(
    const DoFHandler<3> &dof_handler,
    const unsigned int   level,
    const DoFHandler<3> *fine_active_dofs,
    const std::function<
      void(types::global_dof_index, types::global_dof_index, double)> &visit)
  {
    AssertThrow(level > 0 &&
                  level < dof_handler.get_triangulation().n_global_levels(),
                ExcMessage("for_each_prolongation_entry: no level below " +
                           std::to_string(level) + "."));
    const FiniteElement<3>              &fe = dof_handler.get_fe();
    std::vector<types::global_dof_index> parent_dofs(fe.n_dofs_per_cell()),
      child_dofs(fe.n_dofs_per_cell());
    for (const auto &cell : dof_handler.mg_cell_iterators_on_level(level))
      {
        if (!cell->is_locally_owned_on_level())
          continue;
        const auto parent = cell->parent();
        AssertThrow(parent->level_subdomain_id() !=
                      numbers::artificial_subdomain_id,
                    ExcMessage("for_each_prolongation_entry: the parent of "
                               "a cell of this process is not known here."));
        parent->get_mg_dof_indices(parent_dofs);
        if (fine_active_dofs == nullptr)
          cell->get_mg_dof_indices(child_dofs);
        else
          DoFHandler<3>::active_cell_iterator(&dof_handler.get_triangulation(),
                                              cell->level(),
                                              cell->index(),
                                              fine_active_dofs)
            ->get_dof_indices(child_dofs);
        unsigned int c = 0;
        while (parent->child(c) != cell)
          ++c;
        const FullMatrix<double> &child_prolongation =
          fe.get_prolongation_matrix(c, parent->refinement_case());
        for (unsigned int i = 0; i < child_dofs.size(); ++i)
          for (unsigned int j = 0; j < parent_dofs.size(); ++j)
            if (child_prolongation(i, j) != 0)
              visit(child_dofs[i], parent_dofs[j], child_prolongation(i, j));
      }
  }


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
      const IndexSet &fine_boundary =
        constrained_dofs.get_boundary_indices(level);
      const IndexSet &coarse_boundary =
        constrained_dofs.get_boundary_indices(level - 1);
      DynamicSparsityPattern dsp(dof_handler.n_dofs(level),
                                 dof_handler.n_dofs(level - 1));
      std::vector<
        std::tuple<types::global_dof_index, types::global_dof_index, double>>
        entries;
      for_each_prolongation_entry(
        dof_handler,
        level,
        nullptr,
        [&](const auto fine, const auto coarse, const double value) {
          if (!fine_boundary.is_element(fine) &&
              !coarse_boundary.is_element(coarse))
            {
              dsp.add(fine, coarse);
              entries.emplace_back(fine, coarse, value);
            }
        });
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
