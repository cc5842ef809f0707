#ifndef ssc_base_surface_expression_h
#define ssc_base_surface_expression_h

#include <deal.II/base/function_parser.h>

#include <memory>
#include <string>

namespace ssc
{
  using namespace dealii;

  /**
   * A muParser expression of the lateral coordinates x and y (mm), as a
   * parameter gives it (a layer thickness, a ligament density). Parsing
   * throws one message naming @p parameter when the expression is invalid
   * (muParser's own diagnosis, which deal.II prints to stderr, is kept out
   * of the terminal) or uses rand(), which would make every run a
   * different model.
   */
  std::shared_ptr<FunctionParser<2>>
  parse_surface_expression(const std::string &expression,
                           const std::string &parameter);
} // namespace ssc

#endif
