// The line-block preconditioner of the multigrid smoother
// (ssc::LineBlockPreconditioner, ssc::vertical_lines) on a layered
// box with a thin middle layer, Q1 and Q2, active cells and a multigrid
// level:
// - every vertical line of support points gets one number, and the lines
//   have the DoFs of all the nodes across the layers;
// - the preconditioner is the exact inverse of the matrix's line-block
//   diagonal, and it drops the couplings between lines;
// - the DoFs of a line are ordered along it, so its block is banded: the
//   bandwidth is that of the nodes' neighbours across one cell;
// - one line and one position per row are required, and a block that is
//   not positive definite is reported.

#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q1.h>

#include <algorithm>
#include <cctype>
#include <cmath>

#include <ssc/linear_algebra/line_block_preconditioner.h>
#include <ssc/multigrid/vertical_lines.h>

#include "layered_box.h"
#include "tests.h"

using namespace dealii;

namespace
{
  void
  check(const DoFHandler<3> &dof_handler, const unsigned int level)
  {
    const ssc::DoFLines dof_lines =
      ssc::vertical_lines(dof_handler, level, 1e-8);
    const std::vector<unsigned int> &line_of_dof = dof_lines.line;
    const unsigned int               n_lines =
      *std::max_element(line_of_dof.begin(), line_of_dof.end()) + 1;
    std::vector<unsigned int> dofs_on_line(n_lines, 0);
    for (const unsigned int line : line_of_dof)
      ++dofs_on_line[line];
    deallog << (level == numbers::invalid_unsigned_int ?
                  std::string("active") :
                  "level " + std::to_string(level))
            << ": " << line_of_dof.size() << " DoFs, " << n_lines
            << " lines, DoFs per line "
            << *std::min_element(dofs_on_line.begin(), dofs_on_line.end())
            << " to "
            << *std::max_element(dofs_on_line.begin(), dofs_on_line.end())
            << std::endl;

    if (level == numbers::invalid_unsigned_int)
      {
        // every DoF of a line at the same (x, y), different lines apart
        std::map<types::global_dof_index, Point<3>> support;
        DoFTools::map_dofs_to_support_points(MappingQ1<3>(),
                                             dof_handler,
                                             support);
        std::vector<Point<3>> first(n_lines);
        std::vector<bool>     seen(n_lines, false);
        bool                  same = true;
        for (const auto &[dof, x] : support)
          {
            const unsigned int line = line_of_dof[dof];
            if (!seen[line])
              first[line] = x, seen[line] = true;
            same = same && std::abs(first[line][0] - x[0]) < 1e-12 &&
                   std::abs(first[line][1] - x[1]) < 1e-12;
          }
        bool apart = true;
        for (unsigned int a = 0; a < n_lines; ++a)
          for (unsigned int b = a + 1; b < n_lines; ++b)
            apart = apart && (std::abs(first[a][0] - first[b][0]) > 1e-8 ||
                              std::abs(first[a][1] - first[b][1]) > 1e-8);
        deallog << "  a line's DoFs share (x, y): " << (same ? "yes" : "no")
                << ", lines apart: " << (apart ? "yes" : "no") << std::endl;
      }

    SparsityPattern      sparsity;
    SparseMatrix<double> matrix;
    make_layered_matrix(
      dof_handler, level, AffineConstraints<double>(), sparsity, matrix);
    ssc::LineBlockPreconditioner lines;
    lines.initialize(matrix, dof_lines);

    // D x by hand (the couplings within lines), then D^{-1} (D x) = x
    Vector<double> x(matrix.m()), block_product(matrix.m()), result(matrix.m());
    for (unsigned int i = 0; i < x.size(); ++i)
      x(i) = std::sin(1. + 0.37 * i);
    for (unsigned int row = 0; row < matrix.m(); ++row)
      for (auto entry = matrix.begin(row); entry != matrix.end(row); ++entry)
        if (line_of_dof[row] == line_of_dof[entry->column()])
          block_product(row) += entry->value() * x(entry->column());
    lines.vmult(result, block_product);
    result -= x;
    deallog << "  D^{-1} D x = x: relative error "
            << (result.linfty_norm() / x.linfty_norm() < 1e-12 ? "< 1e-12" :
                                                                 "too large")
            << ", lines counted by the preconditioner " << lines.n_lines()
            << ", bandwidth " << lines.max_bandwidth() << std::endl;

    // with the couplings between lines, A x is not D x
    Vector<double> full_product(matrix.m());
    matrix.vmult(full_product, x);
    full_product -= block_product;
    deallog << "  couplings between lines dropped: "
            << (full_product.linfty_norm() >
                    1e-3 * block_product.linfty_norm() ?
                  "yes" :
                  "no")
            << std::endl;
  }
} // namespace


int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();

  // 2 x 2 lateral cells of 1 mm over layers of 1, 0.1 and 1 mm, refined once
  Triangulation<3> tria(Triangulation<3>::limit_level_difference_at_vertices);
  make_layered_box(tria, 1);
  for (const unsigned int degree : {1u, 2u})
    {
      deallog << "Q" << degree << std::endl;
      const FESystem<3> fe(FE_Q<3>(degree), 3);
      DoFHandler<3>     dof_handler(tria);
      dof_handler.distribute_dofs(fe);
      dof_handler.distribute_mg_dofs();
      check(dof_handler, numbers::invalid_unsigned_int);
      check(dof_handler, 0);
    }

  // bad input: too few line numbers; a block that is not positive definite
  const auto refused = [](const std::string &label,
                          const std::string &expected,
                          const auto        &call) {
    try
      {
        call();
        deallog << label << ": accepted" << std::endl;
      }
    catch (const std::exception &error)
      {
        // deal.II wraps the message's lines: compare with single spaces
        std::string message;
        for (const char c : std::string(error.what()))
          if (!std::isspace(c) || (!message.empty() && message.back() != ' '))
            message += std::isspace(c) ? ' ' : c;
        deallog << label << ": refused ("
                << (message.find(expected) != std::string::npos ? "named" :
                                                                  "unnamed")
                << ")" << std::endl;
      }
  };
  SparsityPattern sparsity(2, 2, 1);
  sparsity.compress();
  SparseMatrix<double> matrix(sparsity);
  matrix.set(0, 0, 1.);
  matrix.set(1, 1, -1.);
  ssc::LineBlockPreconditioner lines;
  refused("one line number for two rows",
          "one line and one position per row are needed",
          [&]() {
            lines.initialize(matrix, {{0}, {0.}});
          });
  deallog << "diagonal 1, -1 on one line: "
          << (lines.initialize(matrix, {{0, 0}, {0., 1.}}) ?
                "factorised" :
                "not positive definite, no factor (" +
                  std::to_string(lines.n_lines()) + " lines)")
          << std::endl;
}
