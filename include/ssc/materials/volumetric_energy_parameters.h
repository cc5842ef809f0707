#ifndef ssc_materials_volumetric_energy_parameters_h
#define ssc_materials_volumetric_energy_parameters_h

#include <ssc/materials/material_registry.h>
#include <ssc/materials/volumetric_energy.h>

namespace ssc
{
  /**
   * The parameters of the finite-strain laws that split their energy into
   * an isochoric part and U(J) (corotational, neo-Hookean, Saint
   * Venant-Kirchhoff): which function of J the volumetric energy is. Each of
   * these laws declares it in its own subsection, "Layer
   * stack/<layer>/<law>/Volumetric energy".
   */
  class VolumetricEnergyParameters : public MaterialParameters
  {
  public:
    void
    add_parameters(ParameterHandler &prm) override;

    VolumetricEnergyForm form = VolumetricEnergyForm::logarithmic;
  };
} // namespace ssc

#endif
