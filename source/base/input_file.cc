#include <deal.II/base/exceptions.h>

#include <filesystem>

#include <ssc/base/input_file.h>

namespace ssc
{
  void
  check_input_file(const std::string   &path,
                   const std::string   &name,
                   const std::string   &kind,
                   const std::uintmax_t max_bytes)
  {
    namespace fs = std::filesystem;
    using dealii::ExcMessage;
    std::error_code       error;
    const fs::file_status status = fs::status(path, error);
    AssertThrow(fs::exists(status), ExcMessage(name + " does not exist."));
    AssertThrow(!fs::is_directory(status),
                ExcMessage(name + " is a folder, not " + kind + "."));
    AssertThrow(fs::is_regular_file(status),
                ExcMessage(name +
                           " is not a regular file (a device or a pipe?)."));
    const std::uintmax_t size = fs::file_size(path, error);
    AssertThrow(!error && size <= max_bytes,
                ExcMessage(name + " holds " + std::to_string(size) +
                           " bytes, more than the " +
                           std::to_string(max_bytes >> 20) + " MB " + kind +
                           " may have."));
  }
} // namespace ssc
