#include <ssc/materials/prestretched_material.h>

namespace ssc
{
  PrestretchedMaterial::PrestretchedMaterial(
    std::unique_ptr<const Material> inner_law,
    const double                    prestretch)
    : Material(inner_law->moduli(), inner_law->volumetric().form)
    , inner(std::move(inner_law))
  {
    F_p[0][0] = prestretch;
    F_p[1][1] = prestretch;
    F_p[2][2] = 1. / (prestretch * prestretch);
  }
} // namespace ssc
