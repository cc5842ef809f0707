// Reading the MULTIS in vivo indentation table (data/multis):
// - the shipped file: trials per site, the lines skipped for a missing
//   measurement (8 rows without a muscle thickness), the subjects'
//   covariates (age, sex, BMI, activity level), the probe areas
//   (360 and 675 mm^2, the two transducer faces), and one trial's values
//   checked against the relations the README states (the displacement is
//   the sum of the layers' compressions, TotalStrain x Thickness);
// - bad files, each giving one clear message naming the line or column:
//   a row with a field too few, a value that is not a number, a negative
//   thickness, a header without a column ssc needs, a site list that
//   matches no trial, a file that does not exist, a hexadecimal number,
//   thicknesses, strains and ages outside a human range, a sex other than
//   Female or Male, an activity level the table does not use, a header
//   with two columns of one name, an empty subject, a row given twice, a
//   folder and a device as the file.

#include <boost/algorithm/string/trim.hpp>

#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <set>
#include <sstream>

#include <ssc/identification/indentation_trials.h>

#include "tests.h"

using namespace dealii;

namespace
{
  const std::string data_file =
    SOURCE_DIR "/../data/multis/indentation_trials.csv";

  /// Writes the shipped file's header and first data row, with @p edit
  /// applied to that row, to @p name.
  void
  write_edited_copy(const std::string                        &name,
                    const std::function<void(std::string &)> &edit_header,
                    const std::function<void(std::string &)> &edit_row)
  {
    std::ifstream in(data_file);
    std::string   header, row;
    std::getline(in, header);
    std::getline(in, row);
    edit_header(header);
    edit_row(row);
    std::ofstream out(name);
    out << header << '\n' << row << '\n';
  }

  void
  expect_error(const std::string &label, const std::function<void()> &read)
  {
    try
      {
        read();
        deallog << label << ": no error (wrong)" << std::endl;
      }
    catch (const ExceptionBase &e)
      {
        std::ostringstream info;
        e.print_info(info);
        std::string message = info.str();
        boost::trim(message);
        deallog << label << ": " << message << std::endl;
      }
  }

  /// Replaces the @p index-th comma-separated field of @p row.
  void
  replace_field(std::string       &row,
                const unsigned int index,
                const std::string &value)
  {
    std::size_t begin = 0;
    for (unsigned int i = 0; i < index; ++i)
      begin = row.find(',', begin) + 1;
    const std::size_t end = row.find(',', begin);
    row.replace(begin, end - begin, value);
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();

  const ssc::IndentationData all = ssc::read_indentation_trials(data_file);
  std::map<std::string, unsigned int> per_site;
  std::set<long>                      areas;
  for (const auto &trial : all.trials)
    {
      ++per_site[trial.site];
      areas.insert(std::lround(trial.probe_area));
    }
  deallog << "complete trials: " << all.trials.size() << std::endl;
  for (const auto &[site, n] : per_site)
    deallog << "  " << site << ": " << n << std::endl;
  deallog << "incomplete lines:";
  for (const unsigned int line : all.incomplete_lines)
    deallog << ' ' << line;
  deallog << std::endl << "probe areas (mm^2):";
  for (const long area : areas)
    deallog << ' ' << area;
  deallog << std::endl;

  const ssc::IndentationData forearm =
    ssc::read_indentation_trials(data_file, {"LA_A", "LA_P"});
  const ssc::IndentationTrial &t = forearm.trials.front();
  deallog << "first forearm trial: line " << t.line << ", subject " << t.subject
          << ", " << t.site << ", " << t.sex << ", age " << t.age << ", BMI "
          << t.bmi << ", activity level " << t.activity_level << std::endl
          << "  thicknesses " << t.skin_thickness << ' ' << t.fat_thickness
          << ' ' << t.muscle_thickness << " mm, force " << t.max_force
          << " N, area " << t.probe_area << " mm^2" << std::endl
          << "  strains " << t.skin_strain << ' ' << t.fat_strain << ' '
          << t.muscle_strain << ", displacement " << t.displacement()
          << " mm, stiffness " << t.surface_stiffness << " N/mm" << std::endl;
  // the table's TotalStrain (0.24308663682834242) times its Thickness
  const double table_displacement = 0.24308663682834242 * t.total_thickness();
  deallog << "  displacement - TotalStrain x Thickness: "
          << (std::abs(t.displacement() - table_displacement) < 1e-9 ?
                "below 1e-9 mm" :
                "WRONG")
          << std::endl;

  const auto keep = [](std::string &) {};
  write_edited_copy("field_too_few.csv", keep, [](std::string &row) {
    row = row.substr(0, row.rfind(','));
  });
  expect_error("a field too few",
               [] { ssc::read_indentation_trials("field_too_few.csv"); });
  write_edited_copy("not_a_number.csv", keep, [](std::string &row) {
    replace_field(row, 9, "3.9N");
  });
  expect_error("not a number",
               [] { ssc::read_indentation_trials("not_a_number.csv"); });
  write_edited_copy("negative_thickness.csv", keep, [](std::string &row) {
    replace_field(row, 16, "-3.8");
  });
  expect_error("negative thickness",
               [] { ssc::read_indentation_trials("negative_thickness.csv"); });
  write_edited_copy(
    "no_strain_column.csv",
    [](std::string &header) { replace_field(header, 12, "Fat_Strain"); },
    keep);
  expect_error("header without FatStrain",
               [] { ssc::read_indentation_trials("no_strain_column.csv"); });
  write_edited_copy("one_trial.csv", keep, keep);
  expect_error("unknown site",
               [] { ssc::read_indentation_trials("one_trial.csv", {"XX_A"}); });
  expect_error("missing file",
               [] { ssc::read_indentation_trials("does_not_exist.csv"); });
  write_edited_copy("hexadecimal.csv", keep, [](std::string &row) {
    replace_field(row, 9, "0x10");
  });
  expect_error("hexadecimal number",
               [] { ssc::read_indentation_trials("hexadecimal.csv"); });
  write_edited_copy("thin_skin.csv", keep, [](std::string &row) {
    replace_field(row, 15, "1e-9");
  });
  expect_error("skin of 1e-9 mm",
               [] { ssc::read_indentation_trials("thin_skin.csv"); });
  write_edited_copy("thick_skin.csv", keep, [](std::string &row) {
    replace_field(row, 15, "1e7");
  });
  expect_error("skin of 1e7 mm",
               [] { ssc::read_indentation_trials("thick_skin.csv"); });
  write_edited_copy("large_strain.csv", keep, [](std::string &row) {
    replace_field(row, 12, "7.5");
  });
  expect_error("fat strain 7.5",
               [] { ssc::read_indentation_trials("large_strain.csv"); });
  write_edited_copy("activity.csv", keep, [](std::string &row) {
    replace_field(row, 6, "Very active");
  });
  expect_error("activity level 'Very active'",
               [] { ssc::read_indentation_trials("activity.csv"); });
  write_edited_copy("gender.csv", keep, [](std::string &row) {
    replace_field(row, 4, "female");
  });
  expect_error("gender 'female'",
               [] { ssc::read_indentation_trials("gender.csv"); });
  write_edited_copy("age.csv", keep, [](std::string &row) {
    replace_field(row, 3, "-20");
  });
  expect_error("age -20", [] { ssc::read_indentation_trials("age.csv"); });
  write_edited_copy(
    "two_fat_columns.csv",
    [](std::string &header) { replace_field(header, 7, "Fat"); },
    keep);
  expect_error("two columns named Fat",
               [] { ssc::read_indentation_trials("two_fat_columns.csv"); });
  write_edited_copy("no_subject.csv", keep, [](std::string &row) {
    replace_field(row, 1, "");
  });
  expect_error("empty subject",
               [] { ssc::read_indentation_trials("no_subject.csv"); });
  write_edited_copy("repeated_row.csv", keep, [](std::string &row) {
    row += '\n' + row;
  });
  expect_error("a row twice",
               [] { ssc::read_indentation_trials("repeated_row.csv"); });
  std::filesystem::create_directories("a_folder.csv");
  expect_error("a folder",
               [] { ssc::read_indentation_trials("a_folder.csv"); });
  expect_error("an endless device",
               [] { ssc::read_indentation_trials("/dev/zero"); });
}
