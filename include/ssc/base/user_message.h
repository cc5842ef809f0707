#ifndef ssc_base_user_message_h
#define ssc_base_user_message_h

#include <deal.II/base/exceptions.h>

#include <string>

namespace ssc
{
  using namespace dealii;

  /// The "additional information" of a deal.II exception as one paragraph,
  /// without the source location that is meaningless to a user.
  std::string
  user_message(const ExceptionBase &e);
} // namespace ssc

#endif
