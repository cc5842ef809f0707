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

  constexpr std::array<std::pair<Incision::Shape, const char *>, 3>
  enum_table(Incision::Shape)
  {
    return {{{Incision::Shape::line, "line"},
             {Incision::Shape::disc, "disc"},
             {Incision::Shape::ellipse, "ellipse"}}};
  }

  /**
   * Closure of an elliptic excision (subsection "Incision/Closure"):
   * interrupted sutures across the ellipse's long axis, each gripping the
   * wound's wall through the skin over a bite on either side, drawn
   * together in load steps (SutureTies).
   */
  struct ClosureParameters
  {
    /// Distance between sutures along the long axis, mm (0: no closure).
    double suture_spacing = 0;
    /// The length of wound wall each suture grips, mm.
    double       bite_width       = 1;
    double       suture_stiffness = 100;
    unsigned int load_steps       = 4;

    bool
    enabled() const
    {
      return suture_spacing > 0;
    }
  };

  /**
   * The incision scene (section "Incision"): a straight cut of the
   * pre-tensioned skin through the patch centre, made once along x and
   * once along y, a disc of it excised, or an ellipse excised along x and
   * along y, the wound that opens as the pre-tension comes on, and the
   * ellipse's closure by sutures.
   */
  struct IncisionParameters
  {
    Incision::Shape   shape         = Incision::Shape::line;
    double            length        = 10;
    double            width         = 0;
    std::string       deepest_layer = "skin";
    unsigned int      load_steps    = 4;
    ClosureParameters closure;

    /// The number of models: one for a disc, one per direction otherwise.
    unsigned int
    n_directions() const
    {
      return shape == Incision::Shape::disc ? 1 : 2;
    }

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
