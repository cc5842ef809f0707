#include <deal.II/base/mpi.h>
#include <deal.II/base/subscriptor.h>

#include <deal.II/grid/grid_tools.h>

#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/precondition.h>
#include <deal.II/lac/trilinos_vector.h>

#include <Epetra_CrsMatrix.h>
#include <Epetra_MultiVector.h>

#include <algorithm>
#include <utility>
#include <vector>

#include <ssc/linear_algebra/factor_operator.h>
#include <ssc/linear_algebra/ldlt_preconditioner.h>
#include <ssc/multigrid/distributed_line_blocks.h>
#include <ssc/multigrid/galerkin_hierarchy.h>
#include <ssc/multigrid/geometric_multigrid_preconditioner.h>
#include <ssc/multigrid/vertical_lines.h>

namespace ssc
{
  namespace
  {
    using VectorType = TrilinosWrappers::MPI::Vector;

    /**
     * A distributed matrix as the Chebyshev smoother sees it: Epetra's
     * product, without a copy (the smoother keeps a pointer to its
     * matrix, which deal.II wants to be a Subscriptor; the finest level's
     * matrix is the caller's tangent).
     */
    class EpetraMatrixView : public Subscriptor
    {
    public:
      explicit EpetraMatrixView(const Epetra_CrsMatrix &matrix)
        : matrix(&matrix)
      {}

      void
      vmult(VectorType &dst, const VectorType &src) const
      {
        const int error =
          matrix->Multiply(false, src.trilinos_vector(), dst.trilinos_vector());
        AssertThrow(error == 0, ExcMessage("Epetra's matrix product failed."));
      }

      types::global_dof_index
      m() const
      {
        return matrix->NumGlobalRows64();
      }

      types::global_dof_index
      n() const
      {
        return matrix->NumGlobalCols64();
      }

      const Epetra_CrsMatrix &
      trilinos_matrix() const
      {
        return *matrix;
      }

    private:
      const Epetra_CrsMatrix *matrix;
    };


    /// Sets every zero diagonal entry of this process's rows to one: the
    /// coarse DoFs whose whole support is constrained (their rows and
    /// columns of P^T A P are zero) get the identity.
    void
    set_zero_diagonals_to_one(Epetra_CrsMatrix &matrix)
    {
      const Epetra_Map &rows = matrix.RowMap(), &columns = matrix.ColMap();
      for (int row = 0; row < matrix.NumMyRows(); ++row)
        {
          int     length;
          double *values;
          int    *local_columns;
          matrix.ExtractMyRowView(row, length, values, local_columns);
          for (int k = 0; k < length; ++k)
            if (columns.GID64(local_columns[k]) == rows.GID64(row) &&
                values[k] == 0.)
              values[k] = 1.;
        }
    }
  } // namespace


  /**
   * The hierarchy and the V-cycle, as the Epetra operator CG applies.
   * Level L (the finest) is the field itself: its DoFs, its matrix (not
   * copied), its vectors. The levels below have the level numbers of a
   * second DoFHandler on the same mesh, and their matrices are Galerkin
   * products, computed by Trilinos (EpetraExt) on all processes.
   */
  class GeometricMultigridPreconditioner::VCycle : public FactorOperator
  {
  public:
    VCycle(const DoFHandler<3> &field_dofs, const Epetra_Map &map);

    /// The level matrices, smoothers and coarse factor for @p matrix;
    /// false on every process if a line block of a level matrix is not
    /// positive definite on one, or if the coarsest matrix is singular.
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
      return finest + 1;
    }

  private:
    using Smoother = PreconditionChebyshev<EpetraMatrixView,
                                           VectorType,
                                           DistributedLineBlocks>;

    /// The prolongation from level @p level - 1 to @p level without the
    /// rows of @p constrained (kept in the pattern with zero values, so
    /// that every coarse row of the products has its diagonal).
    void
    make_prolongation(const unsigned int level, const IndexSet &constrained);

    /// solution[level] = (V-cycle) A_level^{-1} defect[level].
    void
    cycle(const unsigned int level) const;

    const DoFHandler<3> &field_dofs;
    DoFHandler<3>        dofs;
    const unsigned int   finest;
    MPI_Comm             communicator;

    /// Per level: this process's DoFs, its vertical lines and their
    /// (x, y), the prolongation from the level below (none on level 0).
    std::vector<IndexSet>                       owned;
    std::vector<DoFLines>                       lines;
    std::vector<std::vector<Point<2>>>          lateral;
    double                                      line_tolerance;
    std::vector<TrilinosWrappers::SparseMatrix> prolongation;
    /// The field's constrained DoFs the finest prolongation is made for.
    IndexSet finest_constrained;

    std::vector<TrilinosWrappers::SparseMatrix>    coarse_matrices;
    std::vector<std::unique_ptr<EpetraMatrixView>> level_matrices;
    std::vector<std::unique_ptr<Smoother>>         smoothers;
    /// the coarsest level's factor (MUMPS L D L^T, on all processes); its
    /// symbolic analysis is kept while the coarse pattern stays the same
    LdltPreconditioner              coarse;
    mutable std::vector<VectorType> defect, solution, residual;
  };


  GeometricMultigridPreconditioner::VCycle::VCycle(
    const DoFHandler<3> &field_dofs,
    const Epetra_Map    &map)
    : FactorOperator(map)
    , field_dofs(field_dofs)
    , dofs(field_dofs.get_triangulation())
    , finest(field_dofs.get_triangulation().n_global_levels() - 1)
    , communicator(field_dofs.get_communicator())
    , owned(finest + 1)
    , lines(finest + 1)
    , lateral(finest + 1)
    , prolongation(finest + 1)
    , coarse_matrices(finest)
    , level_matrices(finest + 1)
    , smoothers(finest + 1)
    , defect(finest + 1)
    , solution(finest + 1)
    , residual(finest + 1)
  {
    dofs.distribute_dofs(field_dofs.get_fe());
    dofs.distribute_mg_dofs();
    // lines closer than a thousandth of the smallest cell are one line
    line_tolerance =
      1e-3 * GridTools::minimal_cell_diameter(dofs.get_triangulation());
    for (unsigned int level = 0; level <= finest; ++level)
      {
        owned[level] = level == finest ? field_dofs.locally_owned_dofs() :
                                         dofs.locally_owned_mg_dofs(level);
        lines[level] =
          level == finest ?
            vertical_lines(field_dofs,
                           numbers::invalid_unsigned_int,
                           line_tolerance,
                           &lateral[level]) :
            vertical_lines(dofs, level, line_tolerance, &lateral[level]);
        defect[level].reinit(owned[level], communicator);
        solution[level].reinit(owned[level], communicator);
        residual[level].reinit(owned[level], communicator);
      }
    for (unsigned int level = 1; level < finest; ++level)
      make_prolongation(level, IndexSet(dofs.n_dofs(level)));
  }


  void
  GeometricMultigridPreconditioner::VCycle::make_prolongation(
    const unsigned int level,
    const IndexSet    &constrained)
  {
    const IndexSet &rows = owned[level];
    // each row once: the cells that share a fine DoF give the same values
    std::vector<std::vector<std::pair<types::global_dof_index, double>>>
      entries(rows.n_elements());
    for_each_prolongation_entry(
      dofs,
      level,
      level == finest ? &field_dofs : nullptr,
      [&](const auto fine, const auto coarse, const double value) {
        if (!rows.is_element(fine))
          return;
        auto &row = entries[rows.index_within_set(fine)];
        if (std::find_if(row.begin(), row.end(), [&](const auto &entry) {
              return entry.first == coarse;
            }) == row.end())
          row.emplace_back(coarse, constrained.is_element(fine) ? 0. : value);
      });

    DynamicSparsityPattern pattern(rows.size(), dofs.n_dofs(level - 1), rows);
    for (unsigned int k = 0; k < entries.size(); ++k)
      {
        AssertThrow(!entries[k].empty(),
                    ExcMessage("GeometricMultigridPreconditioner: a DoF of "
                               "this process is on none of its cells."));
        for (const auto &entry : entries[k])
          pattern.add(rows.nth_index_in_set(k), entry.first);
      }
    prolongation[level].reinit(rows, owned[level - 1], pattern, communicator);
    std::vector<types::global_dof_index> columns;
    std::vector<double>                  values;
    for (unsigned int k = 0; k < entries.size(); ++k)
      {
        columns.clear();
        values.clear();
        for (const auto &entry : entries[k])
          {
            columns.push_back(entry.first);
            values.push_back(entry.second);
          }
        prolongation[level].set(rows.nth_index_in_set(k),
                                columns.size(),
                                columns.data(),
                                values.data());
      }
    prolongation[level].compress(VectorOperation::insert);
  }


  bool
  GeometricMultigridPreconditioner::VCycle::build(
    const TrilinosWrappers::SparseMatrix &matrix,
    const AffineConstraints<double>      &constraints)
  {
    for (auto &smoother : smoothers)
      smoother.reset();
    coarse.clear();

    IndexSet constrained(field_dofs.n_dofs());
    for (const auto dof : owned[finest])
      if (constraints.is_constrained(dof))
        constrained.add_index(dof);
    constrained.compress();
    if (prolongation[finest].m() == 0 || constrained != finest_constrained)
      {
        make_prolongation(finest, constrained);
        finest_constrained = constrained;
      }

    // A_{l-1} = P^T (A_l P), from the finest level's matrix down
    level_matrices[finest] =
      std::make_unique<EpetraMatrixView>(matrix.trilinos_matrix());
    for (unsigned int level = finest; level > 0; --level)
      {
        const TrilinosWrappers::SparseMatrix &fine =
          level == finest ? matrix : coarse_matrices[level];
        TrilinosWrappers::SparseMatrix product;
        fine.mmult(product, prolongation[level]);
        prolongation[level].Tmmult(coarse_matrices[level - 1], product);
        set_zero_diagonals_to_one(const_cast<Epetra_CrsMatrix &>(
          coarse_matrices[level - 1].trilinos_matrix()));
        level_matrices[level - 1] = std::make_unique<EpetraMatrixView>(
          coarse_matrices[level - 1].trilinos_matrix());
      }

    // Chebyshev (degree 4) on the line blocks on every level but the
    // coarsest, which is solved exactly
    bool positive_definite = true;
    for (unsigned int level = 1; level <= finest && positive_definite; ++level)
      {
        auto blocks = std::make_shared<DistributedLineBlocks>();
        positive_definite =
          blocks->initialize(level_matrices[level]->trilinos_matrix(),
                             lines[level],
                             lateral[level],
                             line_tolerance);
        Smoother::AdditionalData data;
        data.smoothing_range     = 15.;
        data.degree              = 4;
        data.eig_cg_n_iterations = 20;
        data.preconditioner      = blocks;
        smoothers[level]         = std::make_unique<Smoother>();
        smoothers[level]->initialize(*level_matrices[level], data);
      }
    if (!positive_definite)
      {
        for (auto &smoother : smoothers)
          smoother.reset();
        return false;
      }
    // a numerically singular coarse matrix: no V-cycle for this tangent
    return coarse.initialize(coarse_matrices[0]);
  }


  void
  GeometricMultigridPreconditioner::VCycle::cycle(
    const unsigned int level) const
  {
    if (level == 0)
      {
        coarse.vmult(solution[0], defect[0]);
        return;
      }
    smoothers[level]->vmult(solution[level], defect[level]);
    level_matrices[level]->vmult(residual[level], solution[level]);
    residual[level].sadd(-1., 1., defect[level]);
    prolongation[level].Tvmult(defect[level - 1], residual[level]);
    cycle(level - 1);
    prolongation[level].vmult_add(solution[level], solution[level - 1]);
    smoothers[level]->step(solution[level], defect[level]);
  }


  int
  GeometricMultigridPreconditioner::VCycle::ApplyInverse(
    const Epetra_MultiVector &X,
    Epetra_MultiVector       &Y) const
  {
    const int n = X.MyLength();
    for (int v = 0; v < X.NumVectors(); ++v)
      {
        std::copy(X[v], X[v] + n, defect[finest].begin());
        cycle(finest);
        std::copy(solution[finest].begin(), solution[finest].end(), Y[v]);
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
  GeometricMultigridPreconditioner::require_uniform_refinements(
    const Triangulation<3> &tria)
  {
    AssertThrow(tria.n_global_levels() >= 2,
                ExcMessage("Elasticity/Linear solver/Preconditioner = gmg "
                           "needs refinement levels: set Mesh/Global "
                           "refinements to 1 or more (and a coarser mesh: "
                           "each refinement has 8 times the cells)."));
    // this process's cells (a distributed mesh keeps far cells coarse)
    bool uniform = true;
    for (const auto &cell : tria.active_cell_iterators())
      if (cell->is_locally_owned() &&
          static_cast<unsigned int>(cell->level()) !=
            tria.n_global_levels() - 1)
        uniform = false;
    AssertThrow(Utilities::MPI::min(uniform ? 1 : 0, tria.get_communicator()) ==
                  1,
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
