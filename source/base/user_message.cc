#include <deal.II/base/utilities.h>

#include <sstream>

#include <ssc/base/user_message.h>

namespace ssc
{
  std::string
  user_message(const ExceptionBase &e)
  {
    std::ostringstream info;
    e.print_info(info);
    const std::string text = Utilities::trim(info.str());
    // collapse deal.II's indented multi-line layout into one paragraph
    std::string collapsed;
    bool        space = false;
    for (const char c : text)
      if (c == '\n' || c == ' ' || c == '\t')
        space = true;
      else
        {
          if (space && !collapsed.empty())
            collapsed += ' ';
          collapsed += c;
          space = false;
        }
    return collapsed;
  }
} // namespace ssc
