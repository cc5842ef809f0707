#ifndef ssc_scenes_model_size_h
#define ssc_scenes_model_size_h

#include <ssc/scenes/parameters.h>

namespace ssc
{
  /**
   * Estimates, from the parameters alone, how large the model of
   * @p parameters will be (background cells, DoFs and memory, lobules,
   * septum triangles, ligament segments, elevation grid points) and throws,
   * naming the parameter to change, where an estimate exceeds its limit in
   * section "Limits". Run by --check and before every run, so that a
   * model that would exhaust the machine is refused before its cost is
   * paid. Stages whose size depends on what came before (local refinement,
   * the DoFs after it) check again when they know it.
   */
  void
  check_model_size(const Parameters &parameters);

  /// Bytes per DoF that a run of polynomial degree @p degree takes, about
  /// (matrix, AMG hierarchy, vectors; measured on the forearm scenes).
  double
  bytes_per_dof(const unsigned int degree);
} // namespace ssc

#endif
