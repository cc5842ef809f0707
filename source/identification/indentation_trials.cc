#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <boost/algorithm/string.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

#include <ssc/base/input_file.h>
#include <ssc/identification/indentation_trials.h>

namespace ssc
{
  using namespace dealii;

  namespace
  {
    std::vector<std::string>
    split_fields(const std::string &line)
    {
      std::vector<std::string> fields;
      boost::split(fields, line, boost::is_any_of(","));
      for (auto &field : fields)
        boost::trim(field);
      return fields;
    }

    bool
    missing(const std::string &field)
    {
      return field.empty() || boost::iequals(field, "nan");
    }

    /// The number in @p field; throws naming the place if it is none.
    double
    number(const std::string &field,
           const std::string &column,
           const std::string &where)
    {
      std::size_t end   = 0;
      double      value = 0;
      // decimal only: std::stod would read 0x10 as 16
      if (field.find_first_not_of("0123456789+-.eE") == std::string::npos)
        try
          {
            value = std::stod(field, &end);
          }
        catch (const std::exception &)
          {
            end = 0;
          }
      AssertThrow(end == field.size() && end > 0 && std::isfinite(value),
                  ExcMessage(where + ": column " + column + " is '" + field +
                             "', not a number."));
      return value;
    }

    /// @p value as a message writes it (six significant digits).
    std::string
    format_number(const double value)
    {
      std::ostringstream text;
      text << value;
      return text.str();
    }
  } // namespace

  IndentationData
  read_indentation_trials(const std::string              &filename,
                          const std::vector<std::string> &sites)
  {
    // a folder or a device (/dev/zero) would be read as an empty or an
    // endless table
    check_input_file(filename,
                     "The indentation data file '" + filename +
                       "' (Identification/Data file)",
                     "a CSV file",
                     64u << 20);
    std::ifstream in(filename);
    AssertThrow(in,
                ExcMessage("The indentation data file '" + filename +
                           "' cannot be read (permissions?)."));
    std::string header_line;
    AssertThrow(std::getline(in, header_line),
                ExcMessage("The indentation data file '" + filename +
                           "' is empty."));
    const std::vector<std::string> header = split_fields(header_line);

    // the columns used, by their names in the MULTIS table
    const std::vector<std::string>      text_columns = {"SubID",
                                                        "Location",
                                                        "Gender",
                                                        "ActivityLevel"};
    const std::vector<std::string>      measured     = {"Age",
                                                        "BMI",
                                                        "Skin",
                                                        "Fat",
                                                        "Muscle",
                                                        "MaxForce",
                                                        "maxForce_normArea",
                                                        "SkinStrain",
                                                        "FatStrain",
                                                        "MuscleStrain",
                                                        "Total_Stiff"};
    std::map<std::string, unsigned int> column;
    for (const auto &name : text_columns)
      column[name] = 0;
    for (const auto &name : measured)
      column[name] = 0;
    for (auto &[name, index] : column)
      {
        const auto found = std::find(header.begin(), header.end(), name);
        AssertThrow(found != header.end(),
                    ExcMessage("The indentation data file '" + filename +
                               "' has no column '" + name +
                               "' (data/multis/README.md lists the columns "
                               "ssc reads)."));
        index = found - header.begin();
        // a second column of the same name would be silently ignored
        const auto again = std::find(found + 1, header.end(), name);
        AssertThrow(again == header.end(),
                    ExcMessage("The indentation data file '" + filename +
                               "' has two columns named '" + name +
                               "' (columns " + std::to_string(index + 1) +
                               " and " +
                               std::to_string(again - header.begin() + 1) +
                               " of the header): rename or remove one."));
      }

    const std::string thickness_range =
      "a layer thickness under the probe lies between " +
      format_number(min_layer_thickness) + " and " +
      format_number(max_layer_thickness) + " mm";
    const std::string strain_range =
      "a layer's compression over its thickness lies between -1 and 1 "
      "(1: squashed to nothing)";
    // the line of each subject's trial at each site: the split is by
    // subject, and the medians count each trial once
    std::map<std::pair<std::string, std::string>, unsigned int> trial_line;

    IndentationData data;
    std::string     line;
    for (unsigned int line_number = 2; std::getline(in, line); ++line_number)
      {
        if (boost::trim_copy(line).empty())
          continue;
        const std::string where =
          filename + ", line " + std::to_string(line_number);
        const std::vector<std::string> fields = split_fields(line);
        AssertThrow(fields.size() == header.size(),
                    ExcMessage(where + ": " + std::to_string(fields.size()) +
                               " fields where the header has " +
                               std::to_string(header.size()) + "."));
        const auto field = [&](const std::string &name) -> const std::string & {
          return fields[column.at(name)];
        };
        if (!sites.empty() &&
            std::find(sites.begin(), sites.end(), field("Location")) ==
              sites.end())
          continue;
        if (std::any_of(measured.begin(),
                        measured.end(),
                        [&](const std::string &name) {
                          return missing(field(name));
                        }))
          {
            data.incomplete_lines.push_back(line_number);
            continue;
          }
        const auto value = [&](const std::string &name) {
          return number(field(name), name, where);
        };

        // a value that lies outside the range of human tissue layers, in
        // its column (the model would otherwise blame a setting it made)
        const auto value_in = [&](const std::string &name,
                                  const double       lower,
                                  const double       upper,
                                  const std::string &range) {
          const double v = value(name);
          AssertThrow(v > lower && v < upper,
                      ExcMessage(where + ": column " + name + " is " +
                                 field(name) + "; " + range + "."));
          return v;
        };
        // the place of a categorical value in the values the table uses
        // (a misspelt one must not count as another category)
        const auto one_of = [&](const std::string              &name,
                                const std::vector<std::string> &values) {
          const auto found =
            std::find(values.begin(), values.end(), field(name));
          AssertThrow(found != values.end(),
                      ExcMessage(where + ": column " + name + " is '" +
                                 field(name) + "'; it is one of " +
                                 boost::algorithm::join(values, ", ") + "."));
          return static_cast<unsigned int>(found - values.begin());
        };

        IndentationTrial trial;
        trial.line    = line_number;
        trial.subject = field("SubID");
        trial.site    = field("Location");
        trial.sex     = field("Gender");
        one_of("Gender", {"Female", "Male"});
        trial.age =
          value_in("Age", 0, 130, "an age lies between 0 and 130 years");
        trial.bmi = value_in("BMI",
                             5,
                             100,
                             "a body-mass index lies between 5 and 100 kg/m^2");
        trial.activity_level =
          one_of("ActivityLevel", {"Sedentary", "Moderately active", "Active"});
        AssertThrow(!trial.subject.empty(),
                    ExcMessage(where + ": column SubID is empty; every "
                                       "trial needs its subject."));
        trial.skin_thickness   = value_in("Skin",
                                        min_layer_thickness,
                                        max_layer_thickness,
                                        thickness_range);
        trial.fat_thickness    = value_in("Fat",
                                       min_layer_thickness,
                                       max_layer_thickness,
                                       thickness_range);
        trial.muscle_thickness = value_in("Muscle",
                                          min_layer_thickness,
                                          max_layer_thickness,
                                          thickness_range);
        trial.max_force        = value("MaxForce");
        const double pressure  = value("maxForce_normArea");
        trial.skin_strain      = value_in("SkinStrain", -1, 1, strain_range);
        trial.fat_strain       = value_in("FatStrain", -1, 1, strain_range);
        trial.muscle_strain    = value_in("MuscleStrain", -1, 1, strain_range);
        AssertThrow(trial.max_force > 0 && pressure > 0,
                    ExcMessage(where + ": MaxForce and maxForce_normArea "
                                       "must be positive."));
        trial.probe_area        = trial.max_force / pressure;
        trial.surface_stiffness = value("Total_Stiff") * trial.probe_area;
        AssertThrow(trial.surface_stiffness > 0,
                    ExcMessage(where + ": Total_Stiff must be positive."));
        const auto [first, is_new] =
          trial_line.emplace(std::make_pair(trial.subject, trial.site),
                             line_number);
        AssertThrow(is_new,
                    ExcMessage(where + " is a second trial of subject " +
                               trial.subject + " at site " + trial.site +
                               " (the first is on line " +
                               std::to_string(first->second) +
                               "): the table holds one trial per subject and "
                               "site; remove the repeated row."));
        data.trials.push_back(trial);
      }
    std::string site_list;
    for (const auto &site : sites)
      site_list += (site_list.empty() ? "" : ", ") + site;
    AssertThrow(
      !data.trials.empty(),
      ExcMessage(
        "The indentation data file '" + filename + "' has no complete trial" +
        (sites.empty() ? std::string() : " at the sites " + site_list) + "."));
    return data;
  }
} // namespace ssc
