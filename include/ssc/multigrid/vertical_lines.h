#ifndef ssc_multigrid_vertical_lines_h
#define ssc_multigrid_vertical_lines_h

#include <deal.II/base/point.h>

#include <deal.II/dofs/dof_handler.h>

#include <vector>

#include <ssc/linear_algebra/line_block_preconditioner.h>

namespace ssc
{
  using namespace dealii;

  /**
   * The vertical lines of DoFs on one multigrid @p level (or on the active
   * cells, level numbers::invalid_unsigned_int): DoFs whose support points
   * have the same (x, y) up to @p tolerance share a line, numbered in the
   * order of increasing (x, y); the position along the line is z. In a
   * layered mesh whose cells are stacked in z (as ssc's and the
   * benchmarks' are) these are the lines across the layers, which the
   * LineBlockPreconditioner solves at once. The support points come from
   * the trilinear map of each cell.
   *
   * On a distributed mesh, the lines of this process's (locally owned)
   * DoFs, numbered in their local order; a line that the partition cuts
   * is two lines on two processes (DistributedLineBlocks joins them).
   * With @p lateral, each line's (x, y) as well.
   */
  DoFLines
  vertical_lines(const DoFHandler<3>   &dof_handler,
                 const unsigned int     level,
                 const double           tolerance,
                 std::vector<Point<2>> *lateral = nullptr);


  /// Orders lateral positions (x, y) by x, then y, equal within a
  /// tolerance: the key of a vertical line.
  struct LateralLess
  {
    double tolerance;

    bool
    operator()(const Point<2> &a, const Point<2> &b) const;
  };
} // namespace ssc

#endif
