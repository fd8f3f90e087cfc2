// Load curves (LS-DYNA *DEFINE_CURVE): piecewise linear in time, constant beyond their ends.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "scene/Scene.hpp"

namespace efg {

double curve_value(const CurveSpec& curve, double time);

/// The factor a load or condition is scaled by: curve name -> value now, the time itself (for
/// values written as expressions of t), and the stage (loads act in the stages they name; ""
/// stands for every stage). Drivers decide what a load without a curve ("") gets (the implicit
/// driver ramps it over the stage).
class LoadFactor {
 public:
  LoadFactor(std::function<double(const std::string& curve)> factor, double time,
             std::string stage = "")
      : factor_(std::move(factor)), time_(time), stage_(std::move(stage)) {}
  double operator()(const std::string& curve) const { return factor_(curve); }
  double time() const { return time_; }
  const std::string& stage() const { return stage_; }

 private:
  std::function<double(const std::string&)> factor_;
  double time_;
  std::string stage_;
};

/// The integral of curve c from t0 to t1 (exact: trapezoids between its breakpoints, constant
/// beyond its ends as curve_value).
double curve_integral(const CurveSpec& c, double t0, double t1);

/// A LoadFactor from the scene's curves at `time`, with `no_curve` for loads without one, in
/// `stage` ("": every load acts).
LoadFactor curve_factor(const Scene& scene, double time, double no_curve,
                        const std::string& stage = "");

}  // namespace efg
