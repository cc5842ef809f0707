#ifndef ssc_scenes_support_conditions_h
#define ssc_scenes_support_conditions_h

#include <vector>

#include <ssc/mechanics/boundary_constraints.h>
#include <ssc/mechanics/elasticity_parameters.h>
#include <ssc/mesh/mesh_parameters.h>

namespace ssc
{
  /// How every scene holds the patch: the bottom fixed, the four sides
  /// free, on rollers or fixed (Elasticity/Sides); for a quarter model the
  /// sides x = 0 and y = 0 are symmetry planes (normal displacement held).
  std::vector<DirichletCondition>
  support_conditions(const SideCondition sides,
                     const MeshSymmetry  symmetry = MeshSymmetry::none);
} // namespace ssc

#endif
