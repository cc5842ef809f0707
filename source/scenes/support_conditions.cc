#include <deal.II/base/function.h>

#include <memory>

#include <ssc/mesh/background_mesh.h>
#include <ssc/scenes/support_conditions.h>

namespace ssc
{
  std::vector<DirichletCondition>
  support_conditions(const SideCondition sides, const MeshSymmetry symmetry)
  {
    auto zero = std::make_shared<Functions::ZeroFunction<3>>(3);
    std::vector<DirichletCondition> conditions;
    conditions.push_back(
      {BoundaryId::bottom, ComponentMask(3, true), zero, {}});
    const bool quarter = symmetry == MeshSymmetry::quarter;
    const bool fixed   = sides == SideCondition::fixed;
    for (const types::boundary_id id : {BoundaryId::x_min,
                                        BoundaryId::x_max,
                                        BoundaryId::y_min,
                                        BoundaryId::y_max})
      {
        const bool symmetry_plane =
          quarter && (id == BoundaryId::x_min || id == BoundaryId::y_min);
        if (sides == SideCondition::free && !symmetry_plane)
          continue;
        // a symmetry plane holds its normal component only
        ComponentMask mask(3, fixed && !symmetry_plane);
        mask.set(id <= BoundaryId::x_max ? 0 : 1, true);
        conditions.push_back({id, mask, zero, {}});
      }
    return conditions;
  }
} // namespace ssc
