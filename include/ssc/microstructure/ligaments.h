#ifndef ssc_microstructure_ligaments_h
#define ssc_microstructure_ligaments_h

#include <deal.II/base/bounding_box.h>
#include <deal.II/base/function_parser.h>
#include <deal.II/base/point.h>

#include <memory>
#include <vector>

#include <ssc/mesh/layer_stack.h>
#include <ssc/microstructure/microstructure_parameters.h>

namespace ssc
{
  /// A skin ligament: a straight cable from the skin to a deeper layer.
  struct Ligament
  {
    Point<3> top;    ///< on the bottom of the skin
    Point<3> bottom; ///< on the top of the target layer (SM or deep)
  };

  /**
   * The ligament density of @p parameters (per cm^2, a function of x and
   * y) over the rectangle where they are drawn: the expected number of
   * ligaments drawn (in the region, or in the whole rectangle with a
   * Realisation half width) and the density's largest sampled value.
   * Throws, naming the parameter, where the density is negative or not
   * finite.
   */
  struct LigamentDensity
  {
    LigamentDensity(const BoundingBox<2>           &rectangle,
                    const MicrostructureParameters &parameters);

    std::shared_ptr<FunctionParser<2>> density;
    double                             expected = 0;
    double                             maximum  = 0;
  };

  /**
   * Places the skin ligaments of the region @p parameters.region, drawn in
   * @p rectangle (its bounding rectangle, or the larger square of the
   * Realisation half width, then cut to the region): their number is the
   * integral of the density (per cm^2) over where they are drawn, rounded;
   * their positions are drawn from the
   * density by rejection sampling (std::mt19937 seeded with the seed), so a
   * density that varies over the patch (buttock, knee) puts more ligaments
   * where it is higher. Each runs from the bottom of the skin (the last
   * skin layer from the top) to the top of the first SM layer below it or
   * to the top of the first deep layer, vertically or at an angle drawn
   * from the Inclination parameters (a line that would leave @p rectangle
   * draws its azimuth again).
   */
  std::vector<Ligament>
  place_ligaments(const LayerStack               &layers,
                  const BoundingBox<2>           &rectangle,
                  const MicrostructureParameters &parameters);
} // namespace ssc

#endif
