// Result files are written atomically: a write that fails (a full disk,
// simulated by a stream that goes bad, and an unwritable target) throws an
// error naming the file, leaves no temporary behind and keeps the earlier
// content; a run removes the result files an earlier run left in its
// folder (and only those); text files arrive whole.

#include <deal.II/base/exceptions.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include <ssc/output/run_output.h>

#include "tests.h"

namespace
{
  std::string
  content(const std::string &file)
  {
    std::ifstream      in(file);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
  }

  /// The message of the error @p write throws, or "no error".
  std::string
  error_of(const std::function<void()> &write)
  {
    try
      {
        write();
      }
    catch (const dealii::ExceptionBase &e)
      {
        std::ostringstream info;
        e.print_info(info);
        return dealii::Utilities::trim(info.str());
      }
    return "no error";
  }
} // namespace


int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  namespace fs             = std::filesystem;
  const std::string folder = "run_output_folder";
  fs::remove_all(folder);
  fs::create_directories(folder);

  // an earlier run's results, and a file of the user's
  for (const std::string name : {"volume_0003.0.vtu",
                                 "volume_0003.pvtu",
                                 "volume.pvd",
                                 "section.csv",
                                 "summary.json",
                                 "summary.json.tmp",
                                 "parameters.prm",
                                 "log.txt",
                                 "notes.txt"})
    std::ofstream(folder + "/" + name) << "old";
  {
    ssc::RunOutput output(folder, MPI_COMM_WORLD, false);
    for (const std::string name :
         {"volume_0003.0.vtu", "summary.json", "summary.json.tmp", "notes.txt"})
      dealii::deallog << name << " after the start of a new run: "
                      << (fs::exists(folder + "/" + name) ? "kept" : "removed")
                      << std::endl;

    output.write_text("table.csv", "a,b\n1,2\n");
    dealii::deallog << "table.csv: " << content(folder + "/table.csv").size()
                    << " bytes, temporary left: "
                    << fs::exists(folder + "/table.csv.tmp") << std::endl;

    // a write that fails half-way keeps the earlier content
    const std::string path    = folder + "/table.csv";
    const std::string message = error_of([&]() {
      ssc::RunOutput::write_atomically(path, [](std::ostream &out) {
        out << "partial";
        out.setstate(std::ios::badbit); // the disk is full
      });
    });
    dealii::deallog << "failed write: "
                    << (message.find("Cannot write '" + path + "'") == 0 ?
                          "names the file" :
                          message)
                    << ", temporary left: " << fs::exists(path + ".tmp")
                    << ", earlier content kept: "
                    << (content(path) == "a,b\n1,2\n") << std::endl;

    // a writer that throws (deal.II's writers do on a failed stream)
    const std::string thrown = error_of([&]() {
      ssc::RunOutput::write_atomically(path, [](std::ostream &) {
        AssertThrow(false, dealii::ExcIO());
      });
    });
    dealii::deallog << "writer that throws: "
                    << (thrown.find("Cannot write") == 0 ? "error" : thrown)
                    << ", earlier content kept: "
                    << (content(path) == "a,b\n1,2\n") << std::endl;

    // a target that cannot be created
    fs::create_directories(folder + "/occupied.csv");
    const std::string occupied =
      error_of([&]() { output.write_text("occupied.csv", "x"); });
    dealii::deallog << "target is a folder: "
                    << (occupied.find("Cannot write") == 0 ? "error" : occupied)
                    << std::endl;
  }
  fs::remove_all(folder);
}
