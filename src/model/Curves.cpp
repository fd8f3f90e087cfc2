#include "model/Curves.hpp"

#include <algorithm>
#include <stdexcept>
#include <vector>

namespace efg {

double curve_value(const CurveSpec& c, double t) {
  if (t <= c.time.front()) return c.value.front();
  if (t >= c.time.back()) return c.value.back();
  const auto it = std::upper_bound(c.time.begin(), c.time.end(), t);
  const auto k = static_cast<std::size_t>(it - c.time.begin());
  const double s = (t - c.time[k - 1]) / (c.time[k] - c.time[k - 1]);
  return c.value[k - 1] + s * (c.value[k] - c.value[k - 1]);
}

double curve_integral(const CurveSpec& c, double t0, double t1) {
  std::vector<double> points = {t0, t1};
  for (double t : c.time)
    if (t > std::min(t0, t1) && t < std::max(t0, t1)) points.push_back(t);
  std::sort(points.begin(), points.end());
  double area = 0;
  for (std::size_t k = 1; k < points.size(); ++k)
    area += 0.5 * (curve_value(c, points[k - 1]) + curve_value(c, points[k])) *
            (points[k] - points[k - 1]);
  return t1 >= t0 ? area : -area;
}

LoadFactor curve_factor(const Scene& scene, double time, double no_curve,
                        const std::string& stage) {
  return LoadFactor(
      [&scene, time, no_curve](const std::string& name) {
        if (name.empty()) return no_curve;
        for (const auto& c : scene.curves)
          if (c.name == name) return curve_value(c, time);
        throw std::logic_error("curve '" + name + "' not found after validation");
      },
      time, stage);
}

}  // namespace efg
