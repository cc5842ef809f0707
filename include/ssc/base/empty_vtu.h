#ifndef ssc_base_empty_vtu_h
#define ssc_base_empty_vtu_h

#include <ostream>

namespace ssc
{
  /// Writes a valid VTU file without cells (deal.II's writers need at least
  /// one patch).
  void
  write_empty_vtu(std::ostream &out);
} // namespace ssc

#endif
