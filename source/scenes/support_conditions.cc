#include <deal.II/base/function.h>

#include <memory>

#include <ssc/mesh/background_mesh.h>
#include <ssc/scenes/support_conditions.h>

namespace ssc
{
  std::vector<DirichletCondition>
  support_conditions(const SideCondition sides)
  {
    auto zero = std::make_shared<Functions::ZeroFunction<3>>(3);
    std::vector<DirichletCondition> conditions;
    conditions.push_back(
      {BoundaryId::bottom, ComponentMask(3, true), zero, {}});
    if (sides == SideCondition::free)
      return conditions;
    const bool fixed = sides == SideCondition::fixed;
    for (const types::boundary_id id : {BoundaryId::x_min,
                                        BoundaryId::x_max,
                                        BoundaryId::y_min,
                                        BoundaryId::y_max})
      {
        ComponentMask mask(3, fixed);
        mask.set(id <= BoundaryId::x_max ? 0 : 1, true);
        conditions.push_back({id, mask, zero, {}});
      }
    return conditions;
  }
} // namespace ssc
