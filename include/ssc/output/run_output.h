#ifndef ssc_output_run_output_h
#define ssc_output_run_output_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/data_out_base.h>
#include <deal.II/base/mpi.h>

#include <nlohmann/json.hpp>

#include <fstream>
#include <functional>
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
   * field family, CSV tables, VTU fields and summary.json. Every file is
   * written under a temporary name, checked and renamed, so that a full
   * disk or a vanished folder gives an error naming the file instead of a
   * truncated result; summary.json comes last, so its presence means a
   * complete run. Result files of an earlier run in the same folder are
   * removed when the run starts (and said so). Every writing function is
   * collective: rank 0 writes (VTU pieces: every rank its own), and an
   * error on any rank is thrown on all. The record lists are members, not
   * statics, so several runs in one process do not leak into each other.
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

    /// How many result files of an earlier run were removed (rank 0).
    unsigned int
    n_removed_files() const
    {
      return n_removed;
    }

    /// Full path of @p file_name in the run folder.
    std::string
    path(const std::string &file_name) const;

    /// Writes @p content into @p file_name (rank 0; collective).
    void
    write_text(const std::string &file_name, const std::string &content) const;

    /// Writes @p file_name through @p write (rank 0; collective).
    void
    write_file(const std::string                         &file_name,
               const std::function<void(std::ostream &)> &write) const;

    /**
     * Writes @p data_out as one VTU piece per rank,
     * <basename>_<step>.<rank>.vtu, and the PVTU record
     * <basename>_<step>.pvtu that lists them; returns the record's name.
     * Collective.
     */
    template <int dim>
    std::string
    write_vtu(const DataOutInterface<dim, 3> &data_out,
              const std::string              &basename,
              const unsigned int              step) const;

    /// Adds a time step to the PVD file <family>.pvd and rewrites it
    /// (collective).
    void
    add_pvd_record(const std::string &family,
                   const double       time,
                   const std::string &vtu_file);

    /// Writes summary.json (rank 0; collective), last of a run's files.
    void
    write_summary(const nlohmann::ordered_json &summary) const;

    /**
     * Writes @p path through @p write under a temporary name in the same
     * folder, checks that every byte reached the disk and renames it; on
     * the calling rank only. Throws an error naming the file otherwise
     * (and leaves no temporary behind).
     */
    static void
    write_atomically(const std::string                         &path,
                     const std::function<void(std::ostream &)> &write);

  private:
    /// Runs @p work on rank 0 and throws on every rank if it failed.
    void
    on_root(const std::function<void()> &work) const;

    /// Removes the result files an earlier run left in the folder (rank 0);
    /// returns how many.
    unsigned int
    remove_stale_results() const;

    std::string  folder;
    MPI_Comm     mpi_communicator;
    bool         is_root;
    unsigned int n_removed = 0;

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
