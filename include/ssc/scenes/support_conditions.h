#ifndef ssc_scenes_support_conditions_h
#define ssc_scenes_support_conditions_h

#include <vector>

#include <ssc/mechanics/boundary_constraints.h>
#include <ssc/mechanics/elasticity_parameters.h>

namespace ssc
{
  /// How every scene holds the patch: the bottom fixed, the four sides
  /// free, on rollers or fixed (Elasticity/Sides).
  std::vector<DirichletCondition>
  support_conditions(const SideCondition sides);
} // namespace ssc

#endif
