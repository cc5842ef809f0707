#ifndef ssc_mechanics_growth_field_h
#define ssc_mechanics_growth_field_h

#include <deal.II/base/point.h>
#include <deal.II/base/quadrature.h>

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/fe/fe_values.h>

#include <functional>
#include <vector>

#include <ssc/mechanics/displacement_field.h>

namespace ssc
{
  /**
   * Isotropic volumetric growth: the material at reference point X takes
   * the stress-free volume (1 + s g(X)) dX, s the growth scale (a load
   * parameter, 1 at first). At finite strain F = F_e F_g with F_g = (1 +
   * s g)^{1/3} I and the energy (1 + s g) W(F_e); at small strain the
   * eigenstrain (s g / 3) I. g is sampled once at the assembly's
   * quadrature points of the locally owned cells.
   */
  class GrowthField
  {
  public:
    /// Growth sampled at the points of @p quadrature (the assembly's).
    explicit GrowthField(const Quadrature<3> &quadrature)
      : quadrature(quadrature)
      , n_points_per_cell(quadrature.size())
    {}

    /// Samples @p growth (of the point and the cell's layer) at the
    /// quadrature points of the locally owned cells of @p field; the scale
    /// starts at 1. Throws if g <= -1 somewhere.
    void
    sample(const DisplacementField &field,
           const std::function<double(const Point<3> &, const unsigned int)>
             &growth);

    /// The points per cell at which growth is sampled.
    unsigned int
    n_points() const
    {
      return n_points_per_cell;
    }

    /// The growth scale s.
    void
    set_scale(const double scale)
    {
      growth_scale = scale;
    }

    /// The growth scale s.
    double
    scale() const
    {
      return growth_scale;
    }

    /// The growth ratio s g at quadrature point @p q of @p cell (0 without
    /// growth).
    double
    at(const DoFHandler<3>::active_cell_iterator &cell,
       const unsigned int                         q) const
    {
      return values.empty() ?
               0. :
               growth_scale *
                 values[cell->active_cell_index() * n_points_per_cell + q];
    }

    /// The stress-free added volume at scale 1, the integral of g (mm^3,
    /// all ranks).
    double
    volume(const DisplacementField &field) const;

  private:
    /// Calls f(index into values, fe_values, q) at every quadrature point
    /// of the locally owned cells of @p field, @p fe_values reinit'ed with
    /// @p flags.
    void
    for_each_point(
      const DisplacementField &field,
      const UpdateFlags        flags,
      const std::function<void(unsigned int, const FEValues<3> &, unsigned int)>
        &f) const;

    /// g at the quadrature points, cell by cell (active cell index times
    /// the points per cell); empty without growth.
    std::vector<double> values;
    const Quadrature<3> quadrature;
    const unsigned int  n_points_per_cell;
    double              growth_scale = 1.;
  };
} // namespace ssc

#endif
