#include <deal.II/base/data_out_base.h>
#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.templates.h>

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <set>
#include <sstream>

#include <ssc/base/collective_error.h>
#include <ssc/output/run_output.h>

namespace ssc
{
  namespace
  {
    /// The list of the files ssc wrote into a run folder.
    const std::string manifest_name = ".ssc_manifest";
    /// The file whose lock a run holds while it writes into the folder.
    const std::string lock_name = ".ssc_lock";

    /// Whether @p name is a plain file name in the folder (a manifest
    /// edited by hand cannot make ssc remove anything outside it).
    bool
    is_plain_name(const std::string &name)
    {
      return !name.empty() && name != "." && name != ".." &&
             name.find('/') == std::string::npos && name != manifest_name &&
             name != lock_name;
    }
  } // namespace


  /// Stream buffer writing to two buffers (stdout and the log file).
  class RunOutput::TeeBuffer : public std::streambuf
  {
  public:
    TeeBuffer(std::streambuf *first, std::streambuf *second)
      : first(first)
      , second(second)
    {}

  protected:
    int
    overflow(int c) override
    {
      if (c == EOF)
        return !EOF;
      const int r1 = first ? first->sputc(c) : c;
      const int r2 = second ? second->sputc(c) : c;
      return (r1 == EOF || r2 == EOF) ? EOF : c;
    }

    int
    sync() override
    {
      const int r1 = first ? first->pubsync() : 0;
      const int r2 = second ? second->pubsync() : 0;
      return (r1 == 0 && r2 == 0) ? 0 : -1;
    }

  private:
    std::streambuf *first;
    std::streambuf *second;
  };


  RunOutput::RunOutput(const std::string &directory,
                       const MPI_Comm     mpi_communicator,
                       const bool         print_to_stdout)
    : folder(directory)
    , mpi_communicator(mpi_communicator)
    , is_root(Utilities::MPI::this_mpi_process(mpi_communicator) == 0)
  {
    // Rank 0 creates the folder; the outcome is shared so that every rank
    // fails together instead of waiting for a rank that gave up.
    on_root([&]() {
      std::error_code error;
      std::filesystem::create_directories(folder, error);
      AssertThrow(!error,
                  ExcMessage("Cannot create the output folder '" + folder +
                             "': " + error.message() +
                             " (Run/Output directory, Run/Name)."));
      lock_folder();
      try
        {
          n_removed = remove_earlier_results();
          n_kept    = count_other_files();
          manifest.open(path(manifest_name), std::ios::trunc);
          record("log.txt");
          log_file.open(path("log.txt"));
          AssertThrow(manifest && log_file,
                      ExcMessage("Cannot write into the output folder '" +
                                 folder +
                                 "' (Run/Output directory, Run/Name)."));
        }
      catch (...)
        {
          ::close(lock_descriptor);
          lock_descriptor = -1;
          throw;
        }
    });
    tee_buffer =
      std::make_unique<TeeBuffer>(print_to_stdout ? std::cout.rdbuf() : nullptr,
                                  is_root ? log_file.rdbuf() : nullptr);
    tee_stream = std::make_unique<std::ostream>(tee_buffer.get());
    pcout      = std::make_unique<ConditionalOStream>(*tee_stream, is_root);
  }


  RunOutput::~RunOutput()
  {
    if (tee_stream)
      tee_stream->flush();
    if (lock_descriptor >= 0)
      ::close(lock_descriptor);
  }


  void
  RunOutput::lock_folder()
  {
    const std::string lock = path(lock_name);
    lock_descriptor = ::open(lock.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    AssertThrow(lock_descriptor >= 0,
                ExcMessage("Cannot create '" + lock +
                           "': " + std::strerror(errno) +
                           " (Run/Output directory, Run/Name)."));
    if (::flock(lock_descriptor, LOCK_EX | LOCK_NB) != 0)
      {
        ::close(lock_descriptor);
        lock_descriptor = -1;
        AssertThrow(false,
                    ExcMessage("Another ssc run is writing into the output "
                               "folder '" +
                               folder + "' (it holds " + lock_name +
                               "): wait until it ends, or give this run its "
                               "own Run/Name or Run/Output directory."));
      }
  }


  unsigned int
  RunOutput::remove_earlier_results() const
  {
    std::ifstream listed(path(manifest_name));
    unsigned int  n = 0;
    std::string   name;
    while (std::getline(listed, name))
      if (is_plain_name(name))
        for (const std::string &file : {name, name + ".tmp"})
          {
            const std::filesystem::path target(path(file));
            std::error_code             error;
            if (!std::filesystem::is_regular_file(
                  std::filesystem::symlink_status(target, error)))
              continue;
            std::filesystem::remove(target, error);
            AssertThrow(!error,
                        ExcMessage("Cannot remove '" + target.string() +
                                   "', a result of an earlier run in the "
                                   "output folder: " +
                                   error.message()));
            ++n;
          }
    return n;
  }


  unsigned int
  RunOutput::count_other_files() const
  {
    unsigned int n = 0;
    for (const auto &entry : std::filesystem::directory_iterator(folder))
      if (is_plain_name(entry.path().filename().string()))
        ++n;
    return n;
  }


  void
  RunOutput::record(const std::string &file_name) const
  {
    if (!recorded.insert(file_name).second)
      return;
    manifest << file_name << '\n' << std::flush;
    AssertThrow(manifest,
                ExcMessage("Cannot write '" + path(manifest_name) +
                           "': " + std::strerror(errno) +
                           " (the list of this run's files; Run/Output "
                           "directory chooses where results go)."));
  }


  void
  RunOutput::on_root(const std::function<void()> &work) const
  {
    std::string problem;
    if (is_root)
      try
        {
          work();
        }
      catch (const ExceptionBase &e)
        {
          std::ostringstream info;
          e.print_info(info);
          problem = Utilities::trim(info.str());
          if (problem.empty())
            problem = e.what();
        }
      catch (const std::exception &e)
        {
          problem = e.what();
        }
    problem = Utilities::MPI::broadcast(mpi_communicator, problem, 0);
    AssertThrow(problem.empty(), ExcMessage(problem));
  }


  void
  RunOutput::write_atomically(const std::string                         &path,
                              const std::function<void(std::ostream &)> &write)
  {
    const std::string temporary = path + ".tmp";
    std::string       problem;
    {
      std::ofstream out(temporary, std::ios::binary);
      if (!out)
        problem = std::strerror(errno);
      else
        {
          try
            {
              write(out);
              out.flush();
            }
          catch (...)
            {
              // deal.II's writers throw ExcIO when the stream fails
              out.setstate(std::ios::badbit);
            }
          if (!out)
            problem = std::strerror(errno);
          out.close();
          if (problem.empty() && out.fail())
            problem = std::strerror(errno);
        }
    }
    std::error_code error;
    if (problem.empty())
      {
        std::filesystem::rename(temporary, path, error);
        if (error)
          problem = error.message();
      }
    if (!problem.empty())
      {
        std::filesystem::remove(temporary, error);
        AssertThrow(false,
                    ExcMessage("Cannot write '" + path + "': " + problem +
                               " (a full disk or a folder without write "
                               "permission? Run/Output directory chooses "
                               "where results go)."));
      }
  }


  std::string
  RunOutput::path(const std::string &file_name) const
  {
    return folder + "/" + file_name;
  }


  void
  RunOutput::write_text(const std::string &file_name,
                        const std::string &content) const
  {
    write_file(file_name, [&content](std::ostream &out) { out << content; });
  }


  void
  RunOutput::write_file(const std::string                         &file_name,
                        const std::function<void(std::ostream &)> &write) const
  {
    on_root([&]() {
      record(file_name);
      write_atomically(path(file_name), write);
    });
  }


  template <int dim>
  std::string
  RunOutput::write_vtu(const DataOutInterface<dim, 3> &data_out,
                       const std::string              &basename,
                       const unsigned int              step) const
  {
    const unsigned int n_ranks =
      Utilities::MPI::n_mpi_processes(mpi_communicator);
    const std::string stem = basename + "_" + Utilities::int_to_string(step, 4);
    const auto        piece = [&](const unsigned int rank) {
      return stem + "." +
             Utilities::int_to_string(rank, Utilities::needed_digits(n_ranks)) +
             ".vtu";
    };
    on_root([&]() {
      for (unsigned int r = 0; r < n_ranks; ++r)
        record(piece(r));
    });
    const unsigned int rank =
      Utilities::MPI::this_mpi_process(mpi_communicator);
    run_collectively(
      [&]() {
        write_atomically(path(piece(rank)),
                         [&](std::ostream &out) { data_out.write_vtu(out); });
      },
      mpi_communicator);
    const std::string record = stem + ".pvtu";
    write_file(record, [&](std::ostream &out) {
      std::vector<std::string> pieces;
      for (unsigned int r = 0; r < n_ranks; ++r)
        pieces.push_back(piece(r));
      data_out.write_pvtu_record(out, pieces);
    });
    return record;
  }


  void
  RunOutput::add_pvd_record(const std::string &family,
                            const double       time,
                            const std::string &vtu_file)
  {
    pvd_records[family].emplace_back(time, vtu_file);
    write_file(family + ".pvd", [&](std::ostream &out) {
      DataOutBase::write_pvd_record(out, pvd_records[family]);
    });
  }


  void
  RunOutput::write_summary(const nlohmann::ordered_json &summary) const
  {
    write_file("summary.json",
               [&](std::ostream &out) { out << summary.dump(2) << '\n'; });
  }


  template std::string
  RunOutput::write_vtu(const DataOutInterface<1, 3> &,
                       const std::string &,
                       const unsigned int) const;
  template std::string
  RunOutput::write_vtu(const DataOutInterface<2, 3> &,
                       const std::string &,
                       const unsigned int) const;
  template std::string
  RunOutput::write_vtu(const DataOutInterface<3, 3> &,
                       const std::string &,
                       const unsigned int) const;
} // namespace ssc
