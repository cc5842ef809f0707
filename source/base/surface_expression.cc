#include <deal.II/base/exceptions.h>

#include <iostream>
#include <sstream>

#include <ssc/base/surface_expression.h>

namespace ssc
{
  std::shared_ptr<FunctionParser<2>>
  parse_surface_expression(const std::string &expression,
                           const std::string &parameter)
  {
    const std::string what = parameter + " = '" + expression + "'";
    AssertThrow(expression.find("rand") == std::string::npos,
                ExcMessage(what + " uses rand(): it must be a deterministic "
                                  "function of x and y (the microstructure "
                                  "has its own seeded randomness)."));
    auto function = std::make_shared<FunctionParser<2>>(1);
    // deal.II prints muParser's diagnosis to stderr before it throws
    std::ostringstream    diagnosis;
    std::streambuf *const cerr_buffer = std::cerr.rdbuf(diagnosis.rdbuf());
    bool                  valid       = true;
    try
      {
        function->initialize("x,y", expression, {});
        // muParser reports unknown symbols only on use
        function->value(Point<2>());
      }
    catch (...)
      {
        valid = false;
      }
    std::cerr.rdbuf(cerr_buffer);
    AssertThrow(valid,
                ExcMessage(what + " is not a number or a valid muParser "
                                  "expression of x and y."));
    return function;
  }
} // namespace ssc
