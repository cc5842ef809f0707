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
#include <set>
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
   * complete run. The folder's manifest (.ssc_manifest) lists every file a
   * run wrote, before it writes it: the next run removes exactly those (and
   * their temporaries) and keeps everything else, so that a user's file or
   * the input of a run is never deleted. A lock (.ssc_lock, released by the
   * system when the process ends, however it ends) keeps a second run out
   * of a folder that a run is writing into. Every writing function is
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

    /// How many files in the folder no ssc run recorded writing; they are
    /// kept (rank 0).
    unsigned int
    n_kept_files() const
    {
      return n_kept;
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

    /// Takes the folder's lock, or throws if another run holds it (rank 0).
    void
    lock_folder();

    /// Removes the files the manifest of an earlier run lists, and their
    /// temporaries (rank 0); returns how many.
    unsigned int
    remove_earlier_results() const;

    /// Counts the files in the folder that are not ssc's own (rank 0).
    unsigned int
    count_other_files() const;

    /// Lists @p file_name in the manifest before it is written (rank 0).
    void
    record(const std::string &file_name) const;

    std::string  folder;
    MPI_Comm     mpi_communicator;
    bool         is_root;
    unsigned int n_removed = 0;
    unsigned int n_kept    = 0;
    /// The lock file's descriptor (rank 0), -1 if none is held.
    int lock_descriptor = -1;
    /// The manifest, open for appending, and the names it lists: they
    /// record what was written, not the state of the results (mutable).
    mutable std::ofstream         manifest;
    mutable std::set<std::string> recorded;

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
