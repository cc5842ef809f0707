#ifndef ssc_mechanics_volume_change_h
#define ssc_mechanics_volume_change_h

#include <ssc/materials/layer_materials.h>
#include <ssc/mechanics/displacement_field.h>

namespace ssc
{
  /**
   * The change of the body's volume at the current displacement of
   * @p field, mm^3: the integral of det F - 1, or of div u in the cells
   * whose law in @p materials is small strain (collective). The growth
   * scene compares it with the stress-free added volume.
   */
  double
  volume_change(const DisplacementField &field,
                const LayerMaterials    &materials);
} // namespace ssc

#endif
