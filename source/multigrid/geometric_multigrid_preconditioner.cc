#include <deal.II/base/mg_level_object.h>

#include <deal.II/grid/grid_tools.h>

#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/precondition.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <Epetra_CrsMatrix.h>
#include <Epetra_MultiVector.h>
#include <deal.II/multigrid/mg_coarse.h>
#include <deal.II/multigrid/mg_constrained_dofs.h>
#include <deal.II/multigrid/mg_matrix.h>
#include <deal.II/multigrid/mg_smoother.h>
#include <deal.II/multigrid/mg_transfer.h>
#include <deal.II/multigrid/multigrid.h>

#include <ssc/linear_algebra/factor_operator.h>
#include <ssc/linear_algebra/line_block_preconditioner.h>
#include <ssc/multigrid/direct_coarse_solver.h>
#include <ssc/multigrid/galerkin_hierarchy.h>
#include <ssc/multigrid/geometric_multigrid_preconditioner.h>
#include <ssc/multigrid/vertical_lines.h>

namespace ssc
{
  /**
   * The hierarchy and the V-cycle, as the Epetra operator CG applies. The
   * mesh's DoFs are numbered again here (with their level numbers); the
   * maps below translate the field's numbering.
   */
  class GeometricMultigridPreconditioner::VCycle : public FactorOperator
  {
  public:
    VCycle(const DoFHandler<3> &field_dofs, const Epetra_Map &map);

    /// The level matrices, smoothers and coarse solve for @p matrix;
    /// false if a line block of a level matrix is not positive definite.
    bool
    build(const TrilinosWrappers::SparseMatrix &matrix,
          const AffineConstraints<double>      &constraints);

    int
    ApplyInverse(const Epetra_MultiVector &X,
                 Epetra_MultiVector       &Y) const override;

    const char *
    Label() const override
    {
      return "ssc geometric multigrid V-cycle";
    }

    unsigned int
    n_levels() const
    {
      return dofs.get_triangulation().n_global_levels();
    }

  private:
    using Smoother = PreconditionChebyshev<SparseMatrix<double>,
                                           Vector<double>,
                                           LineBlockPreconditioner>;

    /// The constrained DoFs on every level: those of @p constraints on
    /// the finest, then each coarse DoF whose node a constrained fine DoF
    /// shares (a nested Lagrange hierarchy puts every coarse node on a
    /// fine one).
    void
    constrain_levels(const AffineConstraints<double> &constraints);

    DoFHandler<3> dofs;
    /// For each DoF of the field: the same DoF's number among the
    /// active DoFs here and on the finest level.
    std::vector<types::global_dof_index> active_of_field, finest_of_field;

    MGConstrainedDoFs                                constrained_dofs;
    MGLevelObject<SparsityPattern>                   sparsity;
    MGLevelObject<SparseMatrix<double>>              matrices;
    MGTransferPrebuilt<Vector<double>>               transfer;
    DirectCoarseSolver                               coarse;
    mg::SmootherRelaxation<Smoother, Vector<double>> smoother;
    mg::Matrix<Vector<double>>                       level_matrices;
    std::unique_ptr<Multigrid<Vector<double>>>       multigrid;
    std::unique_ptr<
      PreconditionMG<3, Vector<double>, MGTransferPrebuilt<Vector<double>>>>
                           preconditioner;
    mutable Vector<double> src, dst;
  };


  GeometricMultigridPreconditioner::VCycle::VCycle(
    const DoFHandler<3> &field_dofs,
    const Epetra_Map    &map)
    : FactorOperator(map)
    , dofs(field_dofs.get_triangulation())
  {
    dofs.distribute_dofs(field_dofs.get_fe());
    dofs.distribute_mg_dofs();
    // every active cell is on the finest level (require_uniform_refinements)
    active_of_field.resize(field_dofs.n_dofs());
    finest_of_field.resize(field_dofs.n_dofs());
    const unsigned int n = field_dofs.get_fe().n_dofs_per_cell();
    std::vector<types::global_dof_index> field_indices(n), active(n), level(n);
    for (const auto &cell : dofs.active_cell_iterators())
      {
        const DoFHandler<3>::active_cell_iterator field_cell(
          &dofs.get_triangulation(), cell->level(), cell->index(), &field_dofs);
        field_cell->get_dof_indices(field_indices);
        cell->get_dof_indices(active);
        cell->get_mg_dof_indices(level);
        for (unsigned int i = 0; i < n; ++i)
          {
            active_of_field[field_indices[i]] = active[i];
            finest_of_field[field_indices[i]] = level[i];
          }
      }
    src.reinit(dofs.n_dofs());
    dst.reinit(dofs.n_dofs());
  }


  void
  GeometricMultigridPreconditioner::VCycle::constrain_levels(
    const AffineConstraints<double> &constraints)
  {
    const unsigned int finest = n_levels() - 1;
    constrained_dofs.initialize(dofs);
    std::vector<IndexSet> boundary(n_levels());
    for (unsigned int level = 0; level < n_levels(); ++level)
      boundary[level] = IndexSet(dofs.n_dofs(level));
    for (types::global_dof_index i = 0; i < finest_of_field.size(); ++i)
      if (constraints.is_constrained(i))
        boundary[finest].add_index(finest_of_field[i]);

    const FiniteElement<3>              &fe = dofs.get_fe();
    std::vector<types::global_dof_index> parent(fe.n_dofs_per_cell()),
      child(fe.n_dofs_per_cell());
    for (unsigned int level = finest; level > 0; --level)
      {
        for (const auto &cell : dofs.mg_cell_iterators_on_level(level - 1))
          {
            cell->get_mg_dof_indices(parent);
            for (unsigned int c = 0; c < cell->n_children(); ++c)
              {
                cell->child(c)->get_mg_dof_indices(child);
                const FullMatrix<double> &prolongation =
                  fe.get_prolongation_matrix(c, cell->refinement_case());
                for (unsigned int i = 0; i < child.size(); ++i)
                  if (boundary[level].is_element(child[i]))
                    for (unsigned int j = 0; j < parent.size(); ++j)
                      if (std::abs(prolongation(i, j) - 1.) < 1e-12)
                        boundary[level - 1].add_index(parent[j]);
              }
          }
      }
    for (unsigned int level = 0; level < n_levels(); ++level)
      {
        boundary[level].compress();
        constrained_dofs.add_boundary_indices(dofs, level, boundary[level]);
      }
  }


  bool
  GeometricMultigridPreconditioner::VCycle::build(
    const TrilinosWrappers::SparseMatrix &matrix,
    const AffineConstraints<double>      &constraints)
  {
    const unsigned int finest = n_levels() - 1;
    // the last V-cycle's objects go first, in the order they refer to each
    // other (deal.II checks that nothing still used is destroyed)
    preconditioner.reset();
    multigrid.reset();
    level_matrices.reset();
    smoother.clear();
    matrices.resize(0, finest);
    sparsity.resize(0, finest);
    constrain_levels(constraints);

    // the finest level's matrix: the assembled one in level numbering (the
    // rows through Epetra's views: deal.II's row iterators copy each row)
    const Epetra_CrsMatrix &crs            = matrix.trilinos_matrix();
    const auto              for_each_entry = [&](const auto &visit) {
      for (int row = 0; row < crs.NumMyRows(); ++row)
        {
          int     length;
          double *values;
          int    *columns;
          crs.ExtractMyRowView(row, length, values, columns);
          const auto level_row = finest_of_field[crs.GRID64(row)];
          for (int k = 0; k < length; ++k)
            visit(level_row,
                  finest_of_field[crs.ColMap().GID64(columns[k])],
                  values[k]);
        }
    };
    DynamicSparsityPattern pattern(dofs.n_dofs(finest));
    for_each_entry([&](const auto row, const auto column, const double) {
      pattern.add(row, column);
    });
    sparsity[finest].copy_from(pattern);
    matrices[finest].reinit(sparsity[finest]);
    for_each_entry([&](const auto row, const auto column, const double value) {
      matrices[finest].set(row, column, value);
    });
    make_galerkin_hierarchy(dofs, constrained_dofs, sparsity, matrices);

    // lines closer than a thousandth of the smallest cell are one line
    const double tolerance =
      1e-3 * GridTools::minimal_cell_diameter(dofs.get_triangulation());
    MGLevelObject<Smoother::AdditionalData> smoother_data(0, finest);
    for (unsigned int level = 0; level <= finest; ++level)
      {
        smoother_data[level].smoothing_range     = 15.;
        smoother_data[level].degree              = 4;
        smoother_data[level].eig_cg_n_iterations = 20;
        auto lines = std::make_shared<LineBlockPreconditioner>();
        if (!lines->initialize(matrices[level],
                               vertical_lines(dofs, level, tolerance)))
          return false;
        smoother_data[level].preconditioner = lines;
      }
    smoother.initialize(matrices, smoother_data);
    coarse.initialize(matrices[0]);
    transfer.initialize_constraints(constrained_dofs);
    transfer.build(dofs);
    level_matrices.initialize(matrices);
    multigrid = std::make_unique<Multigrid<Vector<double>>>(
      level_matrices, coarse, transfer, smoother, smoother);
    preconditioner = std::make_unique<
      PreconditionMG<3, Vector<double>, MGTransferPrebuilt<Vector<double>>>>(
      dofs, *multigrid, transfer);
    return true;
  }


  int
  GeometricMultigridPreconditioner::VCycle::ApplyInverse(
    const Epetra_MultiVector &X,
    Epetra_MultiVector       &Y) const
  {
    for (int v = 0; v < X.NumVectors(); ++v)
      {
        for (types::global_dof_index i = 0; i < active_of_field.size(); ++i)
          src(active_of_field[i]) = X[v][i];
        preconditioner->vmult(dst, src);
        for (types::global_dof_index i = 0; i < active_of_field.size(); ++i)
          Y[v][i] = dst(active_of_field[i]);
      }
    return 0;
  }


  GeometricMultigridPreconditioner::GeometricMultigridPreconditioner(
    const DoFHandler<3> &dof_handler)
    : field_dofs(dof_handler)
  {}


  GeometricMultigridPreconditioner::~GeometricMultigridPreconditioner()
  {
    preconditioner.reset();
  }


  void
  GeometricMultigridPreconditioner::require_one_process(
    const MPI_Comm communicator)
  {
    AssertThrow(Utilities::MPI::n_mpi_processes(communicator) == 1,
                ExcMessage("Elasticity/Linear solver/Preconditioner = gmg "
                           "builds its level matrices on one process: run "
                           "on one MPI rank, or use ldlt (the factor "
                           "distributed over the ranks) or amg."));
  }


  void
  GeometricMultigridPreconditioner::require_uniform_refinements(
    const Triangulation<3> &tria)
  {
    AssertThrow(tria.n_global_levels() >= 2,
                ExcMessage("Elasticity/Linear solver/Preconditioner = gmg "
                           "needs refinement levels: set Mesh/Global "
                           "refinements to 1 or more (and a coarser mesh: "
                           "each refinement has 8 times the cells)."));
    for (const auto &cell : tria.active_cell_iterators())
      AssertThrow(static_cast<unsigned int>(cell->level()) ==
                    tria.n_global_levels() - 1,
                  ExcMessage("Elasticity/Linear solver/Preconditioner = gmg "
                             "needs a mesh of uniform refinements: set "
                             "Mesh/Region of interest/Local refinements to "
                             "0 (refine with Mesh/Global refinements "
                             "instead)."));
  }


  bool
  GeometricMultigridPreconditioner::initialize(
    const TrilinosWrappers::SparseMatrix &matrix,
    const AffineConstraints<double>      &constraints)
  {
    require_one_process(matrix.get_mpi_communicator());
    const Epetra_Map &map = matrix.trilinos_matrix().RowMap();
    preconditioner.reset();
    if (cycle == nullptr || !cycle->OperatorDomainMap().SameAs(map))
      {
        require_uniform_refinements(field_dofs.get_triangulation());
        cycle = std::make_shared<VCycle>(field_dofs, map);
      }
    if (!cycle->build(matrix, constraints))
      {
        cycle.reset();
        return false;
      }
    preconditioner = Teuchos::rcp(cycle.get(), false);
    return true;
  }


  bool
  GeometricMultigridPreconditioner::initialized() const
  {
    return cycle != nullptr && !preconditioner.is_null();
  }


  unsigned int
  GeometricMultigridPreconditioner::n_levels() const
  {
    return cycle == nullptr ? 0 : cycle->n_levels();
  }


  void
  GeometricMultigridPreconditioner::clear()
  {
    PreconditionBase::clear();
    cycle.reset();
  }
} // namespace ssc
