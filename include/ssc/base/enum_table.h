#ifndef ssc_base_enum_table_h
#define ssc_base_enum_table_h

#include <deal.II/base/exceptions.h>
#include <deal.II/base/patterns.h>

#include <array>
#include <memory>
#include <string>
#include <type_traits>
#include <utility>

namespace ssc
{
  using namespace dealii;

  /**
   * @file
   * One table per enumeration. Every enumeration that is a parameter
   * declares, next to its definition,
   * @code
   *   constexpr std::array<std::pair<Enum, const char *>, N>
   *   enum_table(Enum);
   * @endcode
   * (found by argument-dependent lookup). The table is the only place that
   * spells the values: the prm pattern, parsing, printing, summary.json and
   * to_string() all read it, so they cannot drift apart. With the
   * Patterns::Tools::Convert specialisation below,
   * ParameterHandler::add_parameter() binds such an enumeration like a
   * number.
   */

  /// Whether @p Enum has an enum_table().
  template <typename Enum, typename = void>
  struct has_enum_table : std::false_type
  {};

  template <typename Enum>
  struct has_enum_table<Enum,
                        std::void_t<decltype(enum_table(std::declval<Enum>()))>>
    : std::true_type
  {};

  /// The spelling of @p value in its table.
  template <typename Enum,
            typename = std::enable_if_t<has_enum_table<Enum>::value>>
  std::string
  to_string(const Enum value)
  {
    for (const auto &[entry, name] : enum_table(Enum()))
      if (entry == value)
        return name;
    Assert(false, ExcMessage("A value missing from its enum_table()."));
    return "";
  }

  /// The table's spellings separated by '|', as Patterns::Selection wants.
  template <typename Enum>
  std::string
  enum_names()
  {
    std::string names;
    for (const auto &entry : enum_table(Enum()))
      names += (names.empty() ? "" : "|") + std::string(entry.second);
    return names;
  }

  /// The value spelled @p text; throws, listing the choices, if none is.
  template <typename Enum>
  Enum
  enum_from_string(const std::string &text)
  {
    for (const auto &[entry, name] : enum_table(Enum()))
      if (text == name)
        return entry;
    AssertThrow(false,
                ExcMessage("'" + text + "' is not one of " +
                           enum_names<Enum>() + "."));
    return Enum();
  }
} // namespace ssc

namespace dealii::Patterns::Tools
{
  /// Lets ParameterHandler::add_parameter() bind an enumeration that has
  /// an ssc::enum_table(): pattern, default and parsing from the table.
  template <typename Enum>
  struct Convert<Enum, std::enable_if_t<ssc::has_enum_table<Enum>::value>>
  {
    static std::unique_ptr<Patterns::PatternBase>
    to_pattern()
    {
      return std::make_unique<Patterns::Selection>(ssc::enum_names<Enum>());
    }

    static std::string
    to_string(const Enum &value, const Patterns::PatternBase & = *to_pattern())
    {
      return ssc::to_string(value);
    }

    static Enum
    to_value(const std::string &text,
             const Patterns::PatternBase & = *to_pattern())
    {
      return ssc::enum_from_string<Enum>(text);
    }
  };
} // namespace dealii::Patterns::Tools

#endif
