// The Galerkin level matrices of the multigrid hierarchy
// (ssc::make_galerkin_hierarchy) on a layered box with a thin middle layer
// and a coefficient per layer, Q1 and Q2, three levels:
// - where the coarse cells resolve the coefficients and the quadrature is
//   exact, P^T A P equals the matrix assembled on the coarse level, on
//   every level, in the rows and columns of the DoFs that are not on the
//   Dirichlet face;
// - the Dirichlet DoFs' rows and columns are those of the identity;
// - the finest matrix is left as it was;
// - a hierarchy with a matrix missing is refused.

#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>

#include <deal.II/multigrid/mg_constrained_dofs.h>

#include <ssc/multigrid/galerkin_hierarchy.h>

#include "layered_box.h"
#include "tests.h"

using namespace dealii;

namespace
{
  /// Largest |entry| of @p a - @p b over the rows and columns not in
  /// @p boundary, relative to the largest |entry| of @p b there.
  double
  interior_difference(const SparseMatrix<double> &a,
                      const SparseMatrix<double> &b,
                      const IndexSet             &boundary)
  {
    double difference = 0, size = 0;
    for (unsigned int row = 0; row < b.m(); ++row)
      if (!boundary.is_element(row))
        {
          for (auto entry = b.begin(row); entry != b.end(row); ++entry)
            if (!boundary.is_element(entry->column()))
              {
                size       = std::max(size, std::abs(entry->value()));
                difference = std::max(difference,
                                      std::abs(entry->value() -
                                               a.el(row, entry->column())));
              }
          // and nothing in a that b does not have
          for (auto entry = a.begin(row); entry != a.end(row); ++entry)
            if (!boundary.is_element(entry->column()) &&
                b.get_sparsity_pattern().exists(row, entry->column()) == false)
              difference = std::max(difference, std::abs(entry->value()));
        }
    return difference / size;
  }


  /// Whether the rows and columns of @p boundary in @p a are the identity's.
  bool
  identity_on(const SparseMatrix<double> &a, const IndexSet &boundary)
  {
    bool identity = true;
    for (unsigned int row = 0; row < a.m(); ++row)
      for (auto entry = a.begin(row); entry != a.end(row); ++entry)
        if (boundary.is_element(row) || boundary.is_element(entry->column()))
          identity =
            identity && entry->value() == (row == entry->column() ? 1. : 0.);
    return identity;
  }
} // namespace


int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();

  Triangulation<3> tria(Triangulation<3>::limit_level_difference_at_vertices);
  make_layered_box(tria, 2);
  const unsigned int finest = tria.n_levels() - 1;
  for (const unsigned int degree : {1u, 2u})
    {
      const FESystem<3> fe(FE_Q<3>(degree), 3);
      DoFHandler<3>     dof_handler(tria);
      dof_handler.distribute_dofs(fe);
      dof_handler.distribute_mg_dofs();
      MGConstrainedDoFs constrained_dofs;
      constrained_dofs.initialize(dof_handler);
      constrained_dofs.make_zero_boundary_constraints(dof_handler, {4});

      // assembled on every level, and the Galerkin products of the finest
      MGLevelObject<SparsityPattern> assembled_sparsity(0, finest),
        galerkin_sparsity(0, finest);
      MGLevelObject<SparseMatrix<double>> assembled(0, finest),
        galerkin(0, finest);
      for (unsigned int level = 0; level <= finest; ++level)
        {
          AffineConstraints<double> boundary;
          boundary.add_lines(constrained_dofs.get_boundary_indices(level));
          boundary.close();
          make_layered_matrix(dof_handler,
                              level,
                              boundary,
                              assembled_sparsity[level],
                              assembled[level]);
        }
      {
        AffineConstraints<double> boundary;
        boundary.add_lines(constrained_dofs.get_boundary_indices(finest));
        boundary.close();
        make_layered_matrix(dof_handler,
                            finest,
                            boundary,
                            galerkin_sparsity[finest],
                            galerkin[finest]);
      }
      ssc::make_galerkin_hierarchy(dof_handler,
                                   constrained_dofs,
                                   galerkin_sparsity,
                                   galerkin);

      deallog << "Q" << degree << std::endl;
      for (unsigned int level = 0; level <= finest; ++level)
        {
          const IndexSet &boundary =
            constrained_dofs.get_boundary_indices(level);
          const double difference =
            interior_difference(galerkin[level], assembled[level], boundary);
          deallog << "  level " << level << ": " << dof_handler.n_dofs(level)
                  << " DoFs, " << boundary.n_elements()
                  << " on the Dirichlet face; P^T A P against assembled: "
                  << (difference < 1e-12 ? "equal (< 1e-12)" : "differ")
                  << (level < finest ?
                        std::string(", Dirichlet rows and columns: ") +
                          (identity_on(galerkin[level], boundary) ?
                             "identity" :
                             "not identity") :
                        std::string())
                  << std::endl;
        }
    }

  // a hierarchy of two matrices for a mesh of three levels
  MGLevelObject<SparsityPattern>      sparsity(0, 1);
  MGLevelObject<SparseMatrix<double>> matrices(0, 1);
  const FESystem<3>                   fe(FE_Q<3>(1), 3);
  DoFHandler<3>                       dof_handler(tria);
  dof_handler.distribute_dofs(fe);
  dof_handler.distribute_mg_dofs();
  MGConstrainedDoFs constrained_dofs;
  constrained_dofs.initialize(dof_handler);
  try
    {
      ssc::make_galerkin_hierarchy(dof_handler,
                                   constrained_dofs,
                                   sparsity,
                                   matrices);
      deallog << "two matrices for three levels: accepted" << std::endl;
    }
  catch (const std::exception &)
    {
      deallog << "two matrices for three levels: refused" << std::endl;
    }
}
