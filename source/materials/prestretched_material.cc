#include <ssc/materials/prestretched_material.h>

namespace ssc
{
  PrestretchedMaterial::PrestretchedMaterial(
    std::unique_ptr<const Material> inner_law,
    const double                    prestretch)
    : Material(inner_law->moduli(), inner_law->volumetric().form)
    , inner(std::move(inner_law))
    , full_prestretch(prestretch)
  {
    set_fraction(1.);
  }


  void
  PrestretchedMaterial::set_fraction(const double f)
  {
    const double s = 1. + f * (full_prestretch - 1.);
    F_p[0][0]      = s;
    F_p[1][1]      = s;
    F_p[2][2]      = 1. / (s * s);
  }
} // namespace ssc
