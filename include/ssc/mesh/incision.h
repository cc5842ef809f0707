#ifndef ssc_mesh_incision_h
#define ssc_mesh_incision_h

#include <deal.II/grid/tria.h>

#include <array>
#include <string>

namespace ssc
{
  using namespace dealii;

  /**
   * A cut of the top layers of the patch, centred on the patch centre: a
   * straight incision, a segment of the skin surface along x (@p direction
   * 0) or y (1), or an excision, a disc or an ellipse (its long axis along
   * @p direction) of the top layers removed; either down through the top
   * @p n_cut_layers layers. The mesh is cut along it
   * (cut_coarse_mesh()), so its faces are free boundaries (BoundaryId::cut)
   * that the pre-tension of the skin can pull apart. Septa and ligaments
   * need nothing: each of their quadrature points is tied to the one
   * background cell it lies in, so a septum or a ligament that crosses the
   * cut is cut with it (and in an excision, those inside the disc go with
   * its cells).
   */
  struct Incision
  {
    enum class Shape
    {
      line,
      disc,
      ellipse
    };

    Shape shape = Shape::line;
    /// Length of the cut, the disc's diameter or the ellipse's long axis,
    /// mm (0: no cut).
    double length = 0;
    /// The ellipse's short axis, mm.
    double width = 0;
    /// The direction a line (or the ellipse's long axis) runs along: 0 (x)
    /// or 1 (y).
    unsigned int direction = 0;
    /// How many layers, from the skin down, the cut goes through.
    unsigned int n_cut_layers = 1;

    bool
    empty() const
    {
      return length == 0;
    }

    /// The direction across a line (its faces' normal).
    unsigned int
    normal_direction() const
    {
      return 1 - direction;
    }

    /// Whether skin is removed (a disc or an ellipse).
    bool
    excision() const
    {
      return shape != Shape::line;
    }

    /// An excision's semi-axes along x and y, mm: the rim is the ellipse
    /// (x / a_x)^2 + (y / a_y)^2 = 1.
    std::array<double, 2>
    semi_axes() const
    {
      const double along  = length / 2,
                   across = shape == Shape::ellipse ? width / 2 : along;
      return direction == 0 ? std::array<double, 2>{{along, across}} :
                              std::array<double, 2>{{across, along}};
    }
  };

  /**
   * Cuts the coarse mesh @p coarse, given in the layer chart (x, y
   * physical, the layers of unit height stacked below z = 0, @p n_layers
   * of them), along @p incision. A line: every vertex strictly inside the
   * cut's surface is duplicated, and the cells on the positive side of it
   * take the copy; the vertices on the cut's front (its two ends and its
   * floor) stay shared. Throws, naming @p parameter, unless the cut runs
   * along mesh lines (the plane through the centre across @p direction and
   * its two ends are vertex planes of the mesh) and ends inside the patch.
   * An excision: the cells of the cut layers inside the rectangle |x| <
   * a_x, |y| < a_y of the semi-axes are removed, which the layer map's
   * DiskFittingMap of those semi-axes makes a disc or an ellipse (the
   * caller builds the map); its sides must be vertex planes. All boundary faces
   * get the box's colorized ids again, the faces of the cut BoundaryId::cut.
   */
  void
  cut_coarse_mesh(Triangulation<3>  &coarse,
                  const Incision    &incision,
                  const unsigned int n_layers,
                  const std::string &parameter);
} // namespace ssc

#endif
