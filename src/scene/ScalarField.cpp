#include <cmath>
#include <sstream>

#include "core/Errors.hpp"
#include "scene/Scene.hpp"

namespace efg {

double ScalarField::at(const double* p, double t) const {
  if (!expression) return constant;
  const double v = (*expression)(p, t);
  if (!std::isfinite(v)) {
    std::ostringstream o;
    o.precision(10);
    o << where << ": '" << expression->text() << "' is " << (std::isnan(v) ? "nan" : "")
      << (std::isnan(v) ? "" : std::to_string(v).substr(0, std::isinf(v) && v < 0 ? 4 : 3))
      << " at (" << p[0] << ", " << p[1] << ", " << p[2] << ")";
    if (expression->uses_time()) o << ", t = " << t;
    o << "; expected a finite value everywhere it is used";
    throw InputError(o.str());
  }
  return v;
}

bool ScalarField::same_as(const ScalarField& other) const {
  if (varies() != other.varies()) return false;
  return varies() ? expression->text() == other.expression->text() : constant == other.constant;
}

}  // namespace efg
