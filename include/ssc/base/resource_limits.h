#ifndef ssc_base_resource_limits_h
#define ssc_base_resource_limits_h

#include <deal.II/base/parameter_handler.h>

#include <string>

namespace ssc
{
  using namespace dealii;

  /**
   * Section "Limits": how large a model may grow before ssc refuses to
   * build it. Each stage estimates its size before it pays for it (cells
   * before refining, DoFs and memory before the matrix, lobules, septum
   * triangles and ligament segments before the tessellation, grid points
   * before sampling), so that a typo such as a 0.2 mm lobule or a 1e-3 mm
   * triangle stops at once with the parameter to change, instead of
   * running into the machine's memory after minutes.
   */
  struct ResourceLimits
  {
    double max_cells             = 2e6;
    double max_dofs              = 6e6;
    double max_lobules           = 2e5;
    double max_septum_triangles  = 4e6;
    double max_ligament_segments = 1e6;
    double max_grid_points       = 4e6;
    /// Share of the machine's physical memory the estimate may take.
    double memory_fraction = 0.8;

    /// Declares section "Limits", bound to the members.
    void
    add_parameters(ParameterHandler &prm);

    /**
     * Throws unless @p estimate <= @p limit: "<what> would be about
     * <estimate> (Limits/<limit_name> = <limit>): <advice>". Non-finite
     * estimates are refused too.
     */
    static void
    require(const double       estimate,
            const double       limit,
            const std::string &what,
            const std::string &limit_name,
            const std::string &advice);

    /// Throws unless @p bytes fit in memory_fraction of the physical
    /// memory of this machine; @p what says whose memory it is, @p advice
    /// what to change.
    void
    require_memory(const double       bytes,
                   const std::string &what,
                   const std::string &advice) const;

    /// Memory this run may use, bytes: the machine's physical memory, or
    /// less where a cgroup or the address-space limit (ulimit -v) says so.
    static double
    physical_memory();
  };
} // namespace ssc

#endif
