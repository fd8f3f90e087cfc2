// Angles of segments between two probes (angles:), the quantity a springback is read as (the
// NUMISHEET U-channel's flange and wall angles): the angle in the x-y plane of the segment from
// probe `from` to probe `to` in the deformed configuration, written to the run report at the
// end of every stage, so that a springback angle is the difference of two stages' values.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "scene/Scene.hpp"

namespace efg {

/// Fills scene.angles from the resolved document and checks that both ends name probes, and
/// different ones (InputError at file:line:col and key path otherwise).
void read_angle_input(Scene& scene);

/// atan2 in degrees, in (-180, 180], of the deformed segment (X_to + u_to) - (X_from + u_from)
/// in the x-y plane.
double segment_angle_degrees(const std::array<double, 3>& from, const std::array<double, 3>& to,
                             const std::array<double, 2>& u_from,
                             const std::array<double, 2>& u_to);

}  // namespace efg
