#include <deal.II/base/data_out_base.h>
#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.templates.h>

#include <cstdio>
#include <filesystem>
#include <iostream>

#include <ssc/output/run_output.h>

namespace ssc
{
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
    std::string problem;
    if (is_root)
      {
        std::error_code error;
        std::filesystem::create_directories(folder, error);
        if (error)
          problem = "Cannot create the output folder '" + folder +
                    "': " + error.message();
        else
          {
            std::filesystem::remove(path("summary.json"), error);
            log_file.open(path("log.txt"));
            if (!log_file)
              problem = "Cannot write into the output folder '" + folder + "'.";
          }
      }
    problem = Utilities::MPI::broadcast(mpi_communicator, problem, 0);
    AssertThrow(problem.empty(), ExcMessage(problem));
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
    if (!is_root)
      return;
    std::ofstream out(path(file_name));
    AssertThrow(out, ExcMessage("Cannot write " + path(file_name)));
    out << content;
  }


  void
  RunOutput::add_pvd_record(const std::string &family,
                            const double       time,
                            const std::string &vtu_file)
  {
    pvd_records[family].emplace_back(time, vtu_file);
    if (!is_root)
      return;
    std::ofstream out(path(family + ".pvd"));
    DataOutBase::write_pvd_record(out, pvd_records[family]);
  }


  void
  RunOutput::write_summary(const nlohmann::ordered_json &summary) const
  {
    if (!is_root)
      return;
    const std::string temporary = path("summary.json.tmp");
    {
      std::ofstream out(temporary);
      AssertThrow(out, ExcMessage("Cannot write " + temporary));
      out << summary.dump(2) << '\n';
    }
    std::filesystem::rename(temporary, path("summary.json"));
  }
} // namespace ssc
