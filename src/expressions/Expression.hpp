// A scalar expression of position and time from a scene file (LS-DYNA *DEFINE_FUNCTION, MOOSE's
// parsed functions), compiled once by muParser (Debian's libmuparser-dev) to its bytecode and then
// evaluated per point. Variables: x, y, z and t, as far as the place of use allows; named
// constants: the scene's parameters and pi; functions: muParser's built-ins (sin, cos, tan, asin,
// acos, atan, sinh, cosh, tanh, exp, ln, log10, sqrt, abs, sign, min, max, ...) plus atan2(y, x).
//
// Evaluation writes the point into the compiled expression's variables, so one Expression must not
// be evaluated by two threads at once; efg evaluates expressions on the host, serially per rank.
#pragma once

#include <map>
#include <memory>
#include <stdexcept>
#include <string>

namespace efg {

/// A compile error, with the position (0-based character index into the text, -1 when unknown).
class ExpressionError : public std::runtime_error {
 public:
  ExpressionError(const std::string& message, int position)
      : std::runtime_error(message), position_(position) {}
  int position() const { return position_; }

 private:
  int position_;
};

/// Which variables an expression may use where it is written.
enum class ExpressionVariables {
  none,              ///< constants only (parameters, numbers in any scene key)
  position,          ///< x, y, z (initial conditions, exact solutions, mesh maps)
  position_and_time  ///< x, y, z, t (loads, prescribed values)
};

class Expression {
 public:
  /// Compiles `text`; throws ExpressionError. `constants` are the scene's parameters.
  Expression(const std::string& text, const std::map<std::string, double>& constants,
             ExpressionVariables variables);

  /// The value at point p (3 entries, unused ones 0) and time t. May be inf or NaN (division by
  /// zero, a root of a negative number): callers check.
  double operator()(const double* p, double t) const;
  double operator()() const;  ///< for expressions of constants only

  bool uses_position() const { return uses_position_; }
  bool uses_time() const { return uses_time_; }
  const std::string& text() const { return text_; }

  /// The names an expression may use besides its variables (for messages and documentation).
  static std::string builtin_names();

 private:
  struct Compiled;
  std::shared_ptr<Compiled> compiled_;  // shared by copies: evaluation is not thread-safe
  std::string text_;
  bool uses_position_ = false, uses_time_ = false;
};

}  // namespace efg
