// Result files are written atomically: a write that fails (a full disk,
// simulated by a stream that goes bad, and an unwritable target) throws an
// error naming the file, leaves no temporary behind and keeps the earlier
// content; a run removes the files an earlier run listed in the folder's
// manifest (and their temporaries), never a user's file or one outside the
// folder; a second run into a folder being written is refused; text files
// arrive whole.

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

  const auto state = [&](const std::string &name) {
    return name + ": " + (fs::exists(folder + "/" + name) ? "kept" : "removed");
  };

  // files of the user's, in a folder no ssc run wrote into, are kept
  for (const std::string name : {"precious.csv", "config.json", "notes.txt"})
    std::ofstream(folder + "/" + name) << "mine";
  {
    ssc::RunOutput first(folder, MPI_COMM_WORLD, false);
    dealii::deallog << "first run: removed " << first.n_removed_files()
                    << ", kept " << first.n_kept_files() << std::endl;
    first.write_text("summary.json", "{}");
    first.write_text("section.csv", "x\n");
  }
  // the user adds a file; an interrupted write left a temporary
  std::ofstream(folder + "/mine.csv") << "mine";
  std::ofstream(folder + "/section.csv.tmp") << "half";
  // a manifest edited to name a file outside the folder removes nothing
  std::ofstream(folder + "_outside.txt") << "mine";
  std::ofstream(folder + "/.ssc_manifest", std::ios::app)
    << "../" << folder << "_outside.txt\n";
  {
    ssc::RunOutput output(folder, MPI_COMM_WORLD, false);
    dealii::deallog << "second run: removed " << output.n_removed_files()
                    << ", kept " << output.n_kept_files() << std::endl;
    for (const std::string name : {"summary.json",
                                   "section.csv",
                                   "section.csv.tmp",
                                   "precious.csv",
                                   "config.json",
                                   "notes.txt",
                                   "mine.csv"})
      dealii::deallog << state(name) << std::endl;
    dealii::deallog << "file outside the folder: "
                    << (fs::exists(folder + "_outside.txt") ? "kept" :
                                                              "removed")
                    << std::endl;

    // a second run into the folder while this one writes is refused
    const std::string locked =
      error_of([&]() { ssc::RunOutput(folder, MPI_COMM_WORLD, false); });
    dealii::deallog << "concurrent run: "
                    << (locked.find("Another ssc run is writing into the "
                                    "output folder") == 0 ?
                          "refused" :
                          locked)
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
  // the lock goes with the run that held it
  dealii::deallog << "run after the end of the last: " << error_of([&]() {
    ssc::RunOutput(folder, MPI_COMM_WORLD, false);
  }) << std::endl;
  fs::remove_all(folder);
  fs::remove(folder + "_outside.txt");
}
