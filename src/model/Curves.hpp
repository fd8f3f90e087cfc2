// Load curves (LS-DYNA *DEFINE_CURVE): piecewise linear in time, constant beyond their ends.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "scene/Scene.hpp"

namespace efg {

double curve_value(const CurveSpec& curve, double time);

/// The factor a load or condition is scaled by: curve name -> value now. Drivers decide what a
/// load without a curve ("" ) gets (the implicit driver ramps it over the stage).
using LoadFactor = std::function<double(const std::string& curve)>;

/// The integral of curve c from t0 to t1 (exact: trapezoids between its breakpoints, constant
/// beyond its ends as curve_value).
double curve_integral(const CurveSpec& c, double t0, double t1);

/// A LoadFactor from the scene's curves at `time`, with `no_curve` for loads without one.
LoadFactor curve_factor(const Scene& scene, double time, double no_curve);

}  // namespace efg
