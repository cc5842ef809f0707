#ifndef ssc_scenes_incision_parameters_h
#define ssc_scenes_incision_parameters_h

#include <deal.II/base/parameter_handler.h>

#include <array>
#include <string>
#include <utility>

#include <ssc/base/enum_table.h>
#include <ssc/mesh/incision.h>
#include <ssc/mesh/layer_stack.h>

namespace ssc
{
  using namespace dealii;

  constexpr std::array<std::pair<Incision::Shape, const char *>, 2>
  enum_table(Incision::Shape)
  {
    return {{{Incision::Shape::line, "line"}, {Incision::Shape::disc, "disc"}}};
  }

  /**
   * The incision scene (section "Incision"): a straight cut of the
   * pre-tensioned skin through the patch centre, made once along x and
   * once along y, or a disc of it excised, and the wound that opens as the
   * pre-tension comes on.
   */
  struct IncisionParameters
  {
    Incision::Shape shape         = Incision::Shape::line;
    double          length        = 10;
    std::string     deepest_layer = "skin";
    unsigned int    load_steps    = 4;

    /// Declares section "Incision", bound to the members.
    void
    add_parameters(ParameterHandler &prm);

    /// Throws, naming the entry, on values no incision can have.
    void
    check() const;

    /// The cut along @p direction (0 x, 1 y) through the layers of
    /// @p layers down to Deepest layer cut.
    Incision
    incision(const LayerStack &layers, const unsigned int direction) const;
  };
} // namespace ssc

#endif
