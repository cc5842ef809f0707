#ifndef ssc_output_run_output_h
#define ssc_output_run_output_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/mpi.h>

#include <nlohmann/json.hpp>

#include <fstream>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace ssc
{
  using namespace dealii;

  /**
   * The folder output/<run name>/ of one run and what goes into it: a log
   * that mirrors the progress lines printed on rank 0, PVD records per
   * field family, CSV tables and summary.json. Writing happens on rank 0
   * only (VTU pieces excepted, which every rank writes itself). The record
   * lists are members, not statics, so several runs in one process do not
   * leak into each other.
   */
  class RunOutput
  {
  public:
    RunOutput(const std::string &directory,
              const MPI_Comm     mpi_communicator,
              const bool         print_to_stdout);
    ~RunOutput();

    /// Progress stream: stdout (rank 0, unless quiet) and log.txt.
    ConditionalOStream &
    progress()
    {
      return *pcout;
    }

    const std::string &
    directory() const
    {
      return folder;
    }

    /// Full path of @p file_name in the run folder.
    std::string
    path(const std::string &file_name) const;

    /// Writes @p content into @p file_name (rank 0).
    void
    write_text(const std::string &file_name, const std::string &content) const;

    /// Adds a time step to the PVD file <family>.pvd and rewrites it.
    void
    add_pvd_record(const std::string &family,
                   const double       time,
                   const std::string &vtu_file);

    /// Writes summary.json atomically (temporary file, then rename).
    void
    write_summary(const nlohmann::ordered_json &summary) const;

  private:
    std::string folder;
    MPI_Comm    mpi_communicator;
    bool        is_root;

    class TeeBuffer;
    std::ofstream                       log_file;
    std::unique_ptr<TeeBuffer>          tee_buffer;
    std::unique_ptr<std::ostream>       tee_stream;
    std::unique_ptr<ConditionalOStream> pcout;
    std::map<std::string, std::vector<std::pair<double, std::string>>>
      pvd_records;
  };
} // namespace ssc

#endif
