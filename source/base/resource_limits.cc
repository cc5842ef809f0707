#include <deal.II/base/exceptions.h>

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include <ssc/base/resource_limits.h>

namespace ssc
{
  void
  ResourceLimits::add_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Limits");
    prm.add_parameter("Max cells",
                      max_cells,
                      "Background cells (after refinement) beyond which the "
                      "mesh is refused before it is refined.",
                      Patterns::Double(1));
    prm.add_parameter("Max DoFs",
                      max_dofs,
                      "Degrees of freedom beyond which the system is refused "
                      "before its matrix is built.",
                      Patterns::Double(1));
    prm.add_parameter("Max lobules",
                      max_lobules,
                      "Lobule seeds (all fat layers) beyond which the "
                      "microstructure is refused before the tessellation.",
                      Patterns::Double(1));
    prm.add_parameter("Max septum triangles",
                      max_septum_triangles,
                      "Estimated septum triangles beyond which the septa are "
                      "refused before they are meshed.",
                      Patterns::Double(1));
    prm.add_parameter("Max ligament segments",
                      max_ligament_segments,
                      "Ligament segments (ligaments times segments per "
                      "ligament) beyond which the ligaments are refused.",
                      Patterns::Double(1));
    prm.add_parameter("Max grid points",
                      max_grid_points,
                      "Points of the skin-elevation grid of the growth "
                      "scenes beyond which the grid is refused.",
                      Patterns::Double(1));
    prm.add_parameter("Memory fraction",
                      memory_fraction,
                      "Share of this machine's physical memory that the "
                      "estimated memory of the run may take.",
                      Patterns::Double(0.01, 1));
    prm.leave_subsection();
  }


  void
  ResourceLimits::require(const double       estimate,
                          const double       limit,
                          const std::string &what,
                          const std::string &limit_name,
                          const std::string &advice)
  {
    if (std::isfinite(estimate) && estimate <= limit)
      return;
    std::ostringstream message;
    message.precision(3);
    message << what << " would be about " << estimate << " (Limits/"
            << limit_name << " = " << limit << "): " << advice
            << " (or raise Limits/" << limit_name << ").";
    AssertThrow(false, ExcMessage(message.str()));
  }


  void
  ResourceLimits::require_memory(const double       bytes,
                                 const std::string &what,
                                 const std::string &advice) const
  {
    const double available = memory_fraction * physical_memory();
    if (std::isfinite(bytes) && bytes <= available)
      return;
    std::ostringstream message;
    message.precision(3);
    message << what << " would need about " << bytes / 1e9
            << " GB, more than Limits/Memory fraction = " << memory_fraction
            << " of the " << physical_memory() / 1e9
            << " GB this run may use (physical memory, cgroup, ulimit -v): "
            << advice << '.';
    AssertThrow(false, ExcMessage(message.str()));
  }


  double
  ResourceLimits::physical_memory()
  {
    double memory = static_cast<double>(sysconf(_SC_PHYS_PAGES)) *
                    static_cast<double>(sysconf(_SC_PAGE_SIZE));
    // a container's or a shell's limit (ulimit -v) is what the run gets
    std::ifstream cgroup("/sys/fs/cgroup/memory.max");
    double        limit = 0;
    if (cgroup >> limit && limit > 0)
      memory = std::min(memory, limit);
    rlimit address_space;
    if (getrlimit(RLIMIT_AS, &address_space) == 0 &&
        address_space.rlim_cur != RLIM_INFINITY)
      memory = std::min(memory, static_cast<double>(address_space.rlim_cur));
    return memory;
  }
} // namespace ssc
