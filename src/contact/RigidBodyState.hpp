// The state of one rigid body a run carries from step to step and stage to stage: the
// displacement of its reference point from the scene's position and its velocity (translation
// only), and the contact force on it at the last evaluation with its moment about the body's
// reference point (contact::reference_point, moved with the body).
#pragma once

#include <array>

#include "contact/RigidOrientation.hpp"

namespace efg {

struct RigidBodyState {
  std::array<double, 3> displacement{}, velocity{}, force{}, moment{};
  /// Rotating bodies: angular velocity and the rotation accumulated (sum of omega dt; the angle
  /// about z in 2D), both about the reference point.
  std::array<double, 3> angular_velocity{}, rotation{};
  /// 3D: the body's orientation (contact/RigidOrientation.hpp) and, for a free turning body, its
  /// angular momentum about the reference point (world axes)
  contact::Orientation orientation = contact::identity_orientation();
  std::array<double, 3> angular_momentum{};
};

/// The contact force on a body and its moment about the body's reference point.
struct BodyResultant {
  std::array<double, 3> force{}, moment{};
};

}  // namespace efg
