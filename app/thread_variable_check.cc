// DEAL_II_NUM_THREADS checked before deal.II reads it.
//
// deal.II reads DEAL_II_NUM_THREADS while the dynamic loader initialises
// it, and a value that is not a positive number (0, "abc", empty) throws
// there: the process aborts before main() could catch anything or say what
// to change. Functions in an executable's .preinit_array run before any
// library's initialisers, so this check turns such a value into ssc's usual
// error line and exit status 1. It reads the environment from its argument:
// at that point getenv() does not see it yet.

#include <unistd.h>

#include <cstdlib>
#include <cstring>

namespace
{
  /// Writes @p text to stderr (stdio may not be ready this early).
  void
  write_error(const char *text)
  {
    const ssize_t ignored = ::write(STDERR_FILENO, text, std::strlen(text));
    (void)ignored;
  }


  /// Exits with status 1 unless DEAL_II_NUM_THREADS, if set, is a whole
  /// number of threads from 1 to 999999.
  void
  check_thread_variable(int, char **, char **environment)
  {
    const char  name[] = "DEAL_II_NUM_THREADS=";
    const char *value  = nullptr;
    for (char **entry = environment; entry != nullptr && *entry != nullptr;
         ++entry)
      if (std::strncmp(*entry, name, sizeof(name) - 1) == 0)
        value = *entry + sizeof(name) - 1;
    if (value == nullptr)
      return;
    bool         valid  = value[0] >= '1' && value[0] <= '9';
    unsigned int length = 0;
    for (const char *c = value; valid && *c != '\0'; ++c, ++length)
      valid = *c >= '0' && *c <= '9';
    if (valid && length <= 6)
      return;
    write_error("ssc: error: DEAL_II_NUM_THREADS='");
    write_error(value);
    write_error("' must be a whole number of threads, at least 1 (unset it "
                "to use every core).\n");
    std::_Exit(1);
  }


  __attribute__((section(".preinit_array"),
                 used)) void (*const check_before_libraries)(int,
                                                             char **,
                                                             char **) =
    &check_thread_variable;
} // namespace
