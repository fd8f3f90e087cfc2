// The state of one rigid body a run carries from step to step and stage to stage: the
// displacement of its reference point from the scene's position and its velocity (translation
// only), and the contact force on it at the last evaluation.
#pragma once

#include <array>

namespace efg {

struct RigidBodyState {
  std::array<double, 3> displacement{}, velocity{}, force{};
};

}  // namespace efg
