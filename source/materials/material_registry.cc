#include <deal.II/base/exceptions.h>

#include <algorithm>
#include <cctype>

#include <ssc/materials/material_registry.h>

namespace ssc
{
  std::vector<MaterialRegistry::Entry> &
  MaterialRegistry::entries()
  {
    static std::vector<Entry> table;
    return table;
  }


  bool
  MaterialRegistry::add(Entry entry)
  {
    AssertThrow(
      std::none_of(entries().begin(),
                   entries().end(),
                   [&](const Entry &e) { return e.name == entry.name; }),
      ExcMessage("Two materials are registered as '" + entry.name + "'."));
    entries().push_back(std::move(entry));
    return true;
  }


  const MaterialRegistry::Entry &
  MaterialRegistry::get(const std::string &name, const std::string &parameter)
  {
    for (const Entry &entry : entries())
      if (entry.name == name)
        return entry;
    std::string known;
    for (const std::string &n : names())
      known += (known.empty() ? "" : ", ") + n;
    AssertThrow(false,
                ExcMessage(parameter + " = '" + name +
                           "' is not a material model; the registered ones "
                           "are: " +
                           known + "."));
    return entries().front();
  }


  std::vector<std::string>
  MaterialRegistry::names()
  {
    std::vector<std::string> result;
    for (const Entry &entry : entries())
      result.push_back(entry.name);
    // case-insensitive, so that the manual and the tests list them in the
    // order a reader expects
    std::sort(result.begin(),
              result.end(),
              [](const std::string &a, const std::string &b) {
                return std::lexicographical_compare(
                  a.begin(), a.end(), b.begin(), b.end(), [](char x, char y) {
                    return std::tolower(x) < std::tolower(y);
                  });
              });
    return result;
  }


  std::string
  MaterialRegistry::documentation()
  {
    std::string text;
    for (const std::string &name : names())
      text +=
        (text.empty() ? "" : " ") + name + ": " + get(name, "").description;
    return text;
  }
} // namespace ssc
