#include <deal.II/base/exceptions.h>

#include <ssc/scenes/incision_parameters.h>

namespace ssc
{
  void
  IncisionParameters::add_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Incision");
    prm.add_parameter(
      "Shape",
      shape,
      "line: an incision, a straight cut through the patch centre, made "
      "once along x and once along y (two models); disc: an excision, the "
      "cut layers removed inside a disc at the patch centre (one model; "
      "Mesh/Fitted circle radius must be its radius, so that the mesh "
      "lines follow its edge).");
    prm.add_parameter(
      "Length",
      length,
      "Length of the line, or the disc's diameter, mm. Either runs along "
      "mesh lines (Mesh/Layout = box): a line's ends and the square the "
      "disc is mapped from must be vertex planes of the mesh, e.g. an even "
      "multiple of the core's Cell size.",
      Patterns::Double(0));
    prm.add_parameter("Deepest layer cut",
                      deepest_layer,
                      "The cut goes from the skin surface through this "
                      "layer of the Layer stack and every layer above it "
                      "(skin: a cut through the dermis; SAT: into the "
                      "superficial fat as well).",
                      Patterns::Anything());
    prm.add_parameter("Load steps",
                      load_steps,
                      "The skin's pre-tension (Layer stack/<layer>/"
                      "Prestretch) comes on in this many equal steps, the "
                      "wound measured after each.",
                      Patterns::Integer(1, 1000));
    prm.leave_subsection();
  }


  void
  IncisionParameters::check() const
  {
    AssertThrow(length > 0,
                ExcMessage("Incision/Length must be positive (mm)."));
  }


  Incision
  IncisionParameters::incision(const LayerStack  &layers,
                               const unsigned int direction) const
  {
    Incision cut;
    cut.shape     = shape;
    cut.length    = length;
    cut.direction = direction;
    cut.n_cut_layers =
      layers.index_of(deepest_layer, "Incision/Deepest layer cut") + 1;
    return cut;
  }
} // namespace ssc
