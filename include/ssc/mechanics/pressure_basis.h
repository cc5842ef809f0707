#ifndef ssc_mechanics_pressure_basis_h
#define ssc_mechanics_pressure_basis_h

#include <deal.II/base/point.h>

#include <deal.II/dofs/dof_handler.h>

#include <vector>

namespace ssc
{
  using namespace dealii;

  /**
   * The discontinuous pressure (dilatation) space of a cell in the mixed
   * formulations: the constants (P0, n_modes = 1) or the linear functions
   * (P1, n_modes = 4) in the cell's coordinates centred at its centre and
   * scaled by its diameter, for conditioning. Both kernels project the
   * dilatation onto it.
   */
  class PressureBasis
  {
  public:
    PressureBasis(const unsigned int                         n_modes,
                  const DoFHandler<3>::active_cell_iterator &cell)
      : n(n_modes)
      , centre(cell->center())
      , scale(1. / cell->diameter())
    {
      Assert(n_modes == 1 || n_modes == 4, ExcNotImplemented());
    }

    unsigned int
    size() const
    {
      return n;
    }

    /// The basis functions at @p x (real coordinates) into @p values.
    void
    evaluate(const Point<3> &x, std::vector<double> &values) const
    {
      values.resize(n);
      values[0] = 1.;
      for (unsigned int d = 0; d + 1 < n; ++d)
        values[d + 1] = (x[d] - centre[d]) * scale;
    }

  private:
    const unsigned int n;
    const Point<3>     centre;
    const double       scale;
  };
} // namespace ssc

#endif
