#include "model/Curves.hpp"

#include <algorithm>
#include <stdexcept>

namespace efg {

double curve_value(const CurveSpec& c, double t) {
  if (t <= c.time.front()) return c.value.front();
  if (t >= c.time.back()) return c.value.back();
  const auto it = std::upper_bound(c.time.begin(), c.time.end(), t);
  const auto k = static_cast<std::size_t>(it - c.time.begin());
  const double s = (t - c.time[k - 1]) / (c.time[k] - c.time[k - 1]);
  return c.value[k - 1] + s * (c.value[k] - c.value[k - 1]);
}

LoadFactor curve_factor(const Scene& scene, double time, double no_curve) {
  return [&scene, time, no_curve](const std::string& name) {
    if (name.empty()) return no_curve;
    for (const auto& c : scene.curves)
      if (c.name == name) return curve_value(c, time);
    throw std::logic_error("curve '" + name + "' not found after validation");
  };
}

}  // namespace efg
