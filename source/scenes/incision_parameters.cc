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
      "lines follow its edge); ellipse: an excision of an ellipse, Length "
      "by Width, its long axis once along x and once along y (two models; "
      "the mesh lines follow its edge by its own map, no Fitted circle "
      "radius).");
    prm.add_parameter(
      "Length",
      length,
      "Length of the line, the disc's diameter or the ellipse's long axis, "
      "mm. Each runs along mesh lines (Mesh/Layout = box): a line's ends "
      "and the rectangle the disc or ellipse is mapped from must be vertex "
      "planes of the mesh, e.g. an even multiple of the core's Cell size.",
      Patterns::Double(0));
    prm.add_parameter("Width",
                      width,
                      "The ellipse's short axis, mm (Shape = ellipse only; "
                      "an even multiple of the core's Cell size). Surgical "
                      "ellipses are about three times as long as wide.",
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
    prm.enter_subsection("Closure");
    prm.add_parameter(
      "Suture spacing",
      closure.suture_spacing,
      "Closes an elliptic excision (after the pre-tension) with interrupted "
      "sutures across its long axis, this far apart (mm) along it, one at "
      "the centre; each grips the wound's wall through the skin on both "
      "sides (Bite width) and draws the two bites together. 0: no "
      "closure.",
      Patterns::Double(0));
    prm.add_parameter(
      "Bite width",
      closure.bite_width,
      "The length of the wound's wall (mm, along its long axis) each "
      "suture grips on either side, through the skin's thickness; its "
      "force is spread over that patch. A finite bite makes the force a "
      "property of the tissue (a tie of single mesh vertices would need "
      "less force on every finer mesh). At most the spacing.",
      Patterns::Double(0));
    prm.add_parameter(
      "Suture stiffness",
      closure.suture_stiffness,
      "Penalty stiffness of a suture, N/mm, between the mean positions of "
      "its two bites: the closed bites stay apart by force / stiffness, "
      "which summary.json reports (closure residual_gap_mm).",
      Patterns::Double(0));
    prm.add_parameter("Load steps",
                      closure.load_steps,
                      "The sutures draw the lips together in this many "
                      "equal steps, the closure measured after each.",
                      Patterns::Integer(1, 1000));
    prm.leave_subsection();
    prm.leave_subsection();
  }


  void
  IncisionParameters::check() const
  {
    AssertThrow(length > 0,
                ExcMessage("Incision/Length must be positive (mm)."));
    AssertThrow(shape == Incision::Shape::ellipse ?
                  width > 0 && width <= length :
                  width == 0,
                ExcMessage("Incision/Width: an ellipse needs a width (its "
                           "short axis, mm) between 0 and Length; a line or "
                           "a disc has none (leave it 0)."));
    AssertThrow(!closure.enabled() || shape == Incision::Shape::ellipse,
                ExcMessage("Incision/Closure/Suture spacing > 0 closes an "
                           "elliptic excision: set Incision/Shape = "
                           "ellipse, or the spacing to 0."));
    AssertThrow(!closure.enabled() || closure.suture_stiffness > 0,
                ExcMessage("Incision/Closure/Suture stiffness must be "
                           "positive (N/mm)."));
    AssertThrow(!closure.enabled() ||
                  (closure.bite_width > 0 &&
                   closure.bite_width <= closure.suture_spacing),
                ExcMessage("Incision/Closure/Bite width = " +
                           std::to_string(closure.bite_width) +
                           " mm must be positive and at most the Suture "
                           "spacing (" +
                           std::to_string(closure.suture_spacing) +
                           " mm): wider bites would overlap, two sutures "
                           "gripping the same tissue."));
    AssertThrow(!closure.enabled() || closure.bite_width < length,
                ExcMessage("Incision/Closure/Bite width must be shorter "
                           "than the ellipse (Incision/Length)."));
  }


  Incision
  IncisionParameters::incision(const LayerStack  &layers,
                               const unsigned int direction) const
  {
    Incision cut;
    cut.shape     = shape;
    cut.length    = length;
    cut.width     = width;
    cut.direction = direction;
    cut.n_cut_layers =
      layers.index_of(deepest_layer, "Incision/Deepest layer cut") + 1;
    return cut;
  }
} // namespace ssc
