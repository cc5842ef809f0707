#ifndef ssc_base_input_file_h
#define ssc_base_input_file_h

#include <cstdint>
#include <string>

namespace ssc
{
  /**
   * Throws, starting the message with @p name (e.g. "The parameter file
   * 'a.prm'"), unless @p path is an existing regular file of at most
   * @p max_bytes: a folder would read as an empty file, a device such as
   * /dev/zero as an endless one, and a huge file as the memory running
   * out. @p kind says what the file should be (e.g. "a .prm file").
   */
  void
  check_input_file(const std::string &path,
                   const std::string &name,
                   const std::string &kind,
                   std::uintmax_t     max_bytes);
} // namespace ssc

#endif
