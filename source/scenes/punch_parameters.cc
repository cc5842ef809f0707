#include <ssc/scenes/punch_parameters.h>

namespace ssc
{
  void
  PunchParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Punch");
    prm.declare_entry("Radius",
                      "2.5",
                      Patterns::Double(0),
                      "Radius a of the rigid flat cylindrical punch, mm "
                      "(the forearm studies use a 5 mm diameter).");
    prm.declare_entry("Depth",
                      "0.5",
                      Patterns::Double(0),
                      "Prescribed indentation depth delta at the last load "
                      "step, mm (positive into the body).");
    prm.declare_entry("Contact",
                      "bonded",
                      Patterns::Selection("bonded|frictionless"),
                      "bonded: the skin under the punch moves with it (u = "
                      "(0, 0, -delta)); frictionless: only u_z = -delta is "
                      "imposed and the skin slides freely (Sneddon 1965).");
    prm.declare_entry("Load steps",
                      "1",
                      Patterns::Integer(1, 1000),
                      "Number of equal depth increments; the force is "
                      "reported after each.");
    prm.leave_subsection();
  }


  void
  PunchParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Punch");
    radius     = prm.get_double("Radius");
    depth      = prm.get_double("Depth");
    contact    = prm.get("Contact") == "frictionless" ?
                   PunchContact::frictionless :
                   PunchContact::bonded;
    load_steps = prm.get_integer("Load steps");
    prm.leave_subsection();
    AssertThrow(radius > 0, ExcMessage("Punch/Radius must be positive (mm)."));
  }
} // namespace ssc
