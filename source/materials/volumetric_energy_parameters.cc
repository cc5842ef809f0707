#include <ssc/base/enum_table.h>
#include <ssc/materials/volumetric_energy_parameters.h>

namespace ssc
{
  void
  VolumetricEnergyParameters::add_parameters(ParameterHandler &prm)
  {
    prm.add_parameter(
      "Volumetric energy",
      form,
      "U(J) = kappa/4 (J^2 - 1 - 2 ln J) (logarithmic) or kappa/2 (J - 1)^2 "
      "(quadratic, the NEO HOOKE of CalculiX and Abaqus with D1 = "
      "2/kappa). Equal to second order in J - 1; at nu = 0.49 a punch "
      "drives the fat far enough from J = 1 for the choice to show.");
  }
} // namespace ssc
