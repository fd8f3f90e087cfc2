#include "expressions/Expression.hpp"

#include <muParser.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <regex>

namespace efg {

struct Expression::Compiled {
  mu::Parser parser;
  double x = 0, y = 0, z = 0, t = 0;  // the variables muParser reads through pointers
};

namespace {

double two_argument_atan(double y, double x) {
  return std::atan2(y, x);
}

const char* variable_list(ExpressionVariables v) {
  switch (v) {
    case ExpressionVariables::none:
      return "no variables (numbers and parameters only)";
    case ExpressionVariables::position:
      return "the variables x, y, z";
    default:
      return "the variables x, y, z, t";
  }
}

// A number too large for a double (1e400): muParser's reader fails on it and reports the token as
// an unknown name; the YAML reader, too, leaves such a number to the expression. The literal at
// `at` (muParser's token position; its token may hold only the digits before '.' or 'e'), when
// it overflows; "" otherwise.
std::string overflowing_number(const std::string& text, int at) {
  if (at < 0 || at >= static_cast<int>(text.size())) return "";
  const std::string token = text.substr(static_cast<std::size_t>(at));
  static const std::regex literal("^([0-9]+\\.?[0-9]*|\\.[0-9]+)[eE][-+]?[0-9]+");
  std::smatch m;
  if (!std::regex_search(token, m, literal)) return "";
  errno = 0;
  const double v = std::strtod(m.str().c_str(), nullptr);
  return errno == ERANGE && std::isinf(v) ? m.str() : "";
}

// muParser's messages end with "at position N." (1-based); ours name the position in the caller's
// file:line:col instead, so only the reason is kept, with a plainer wording for the common cases.
std::string reason(const mu::ParserError& e, ExpressionVariables v, const std::string& text) {
  const auto& token = e.GetToken();
  switch (e.GetCode()) {
    case mu::ecUNASSIGNABLE_TOKEN:
      if (const auto number = overflowing_number(text, e.GetPos()); !number.empty())
        return "the number " + number +
               " is out of the range of double (overflow; magnitudes up to 1.8e308)";
      return "unknown name '" + token + "' (allowed here: " + variable_list(v) +
             ", the scene's parameters and " + Expression::builtin_names() + ")";
    case mu::ecUNEXPECTED_EOF:
      return "the expression ends too early (a missing operand or ')')";
    case mu::ecMISSING_PARENS:
      return "missing ')'";
    case mu::ecTOO_MANY_PARAMS:
      return "too many arguments for function '" + token + "'";
    case mu::ecTOO_FEW_PARAMS:
      return "too few arguments for function '" + token + "'";
    case mu::ecUNEXPECTED_ARG_SEP:
      return "unexpected ',' (one value expected)";
    default: {
      auto m = std::regex_replace(e.GetMsg(), std::regex(" at position [0-9]+\\.?$"), "");
      return m.empty() ? "malformed expression" : m;
    }
  }
}

// muParser accepts assignments to variables ("x = 2"); a scene value must not change them.
int assignment_position(const std::string& text) {
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] != '=') continue;
    const char before = i > 0 ? text[i - 1] : ' ';
    const char after = i + 1 < text.size() ? text[i + 1] : ' ';
    if (after == '=' || before == '=' || before == '<' || before == '>' || before == '!') continue;
    return static_cast<int>(i > 0 && std::string("+-*/").find(before) != std::string::npos ? i - 1
                                                                                           : i);
  }
  return -1;
}

}  // namespace

std::string Expression::builtin_names() {
  return "pi, sin, cos, tan, asin, acos, atan, atan2, sinh, cosh, tanh, exp, ln, log10, sqrt, "
         "abs, sign, min, max";
}

Expression::Expression(const std::string& text, const std::map<std::string, double>& constants,
                       ExpressionVariables variables)
    : compiled_(std::make_shared<Compiled>()), text_(text) {
  const auto first = text.find_first_not_of(" \t");
  if (first == std::string::npos) throw ExpressionError("empty expression", 0);
  if (const int at = assignment_position(text); at >= 0)
    throw ExpressionError("'=' is not allowed (compare with '==')", at);
  auto& p = compiled_->parser;
  try {
    p.DefineConst("pi", M_PI);
    p.DefineFun("atan2", two_argument_atan);
    for (const auto& [name, value] : constants) p.DefineConst(name, value);
    if (variables != ExpressionVariables::none) {
      p.DefineVar("x", &compiled_->x);
      p.DefineVar("y", &compiled_->y);
      p.DefineVar("z", &compiled_->z);
    }
    if (variables == ExpressionVariables::position_and_time) p.DefineVar("t", &compiled_->t);
    p.SetExpr(text);
    // Eval parses with the defined names only (every syntax error and unknown name surfaces
    // here) and compiles to bytecode; GetUsedVar afterwards (it tolerates unknown names).
    p.Eval();
    const auto used = p.GetUsedVar();
    uses_time_ = used.count("t") > 0;
    uses_position_ = used.count("x") + used.count("y") + used.count("z") > 0;
    if (p.GetNumResults() != 1)
      throw ExpressionError(
          "one value expected, found " + std::to_string(p.GetNumResults()) + " separated by ','",
          static_cast<int>(text.find(',')));
  } catch (const mu::ParserError& e) {
    // GetPos is muParser's 0-based index of the offending token (-1 when unknown).
    // at the end of the text muParser may point one past it
    throw ExpressionError(reason(e, variables, text),
                          std::min(e.GetPos(), static_cast<int>(text.size())));
  }
}

double Expression::operator()(const double* point, double t) const {
  auto& c = *compiled_;
  c.x = point[0];
  c.y = point[1];
  c.z = point[2];
  c.t = t;
  return c.parser.Eval();
}

double Expression::operator()() const {
  return compiled_->parser.Eval();
}

}  // namespace efg
