// Reads rigid_bodies[] and contacts[] into the scene and cross-checks them beyond the schema:
// names that exist (curves, bodies, parts; a contact between two rigid bodies is refused), one
// mass description (a free body needs mass, or density and a shape with a volume), a prescribed
// motion with a velocity, box corners in order, a nonzero plane normal, and in a scene with an
// implicit stage frictionless contacts with fixed bodies only. Dimensions against the mesh are
// checked with it (scene/SceneMeshChecks).
#pragma once

#include "scene/Scene.hpp"

namespace efg {

/// Volume of a body's shape in a dim-D model (2D: area x thickness); 0 when it has none (plane,
/// infinite 3D cylinder).
double rigid_body_volume(const RigidBodySpec& body, int dim);
/// Its mass: given, or density x volume.
inline double rigid_body_mass(const RigidBodySpec& body, int dim) {
  return body.mass > 0 ? body.mass : body.density * rigid_body_volume(body, dim);
}

/// Fills scene.rigid_bodies and scene.contacts from scene.resolved; throws InputError at
/// file:line:col and key path for the first problem.
void read_contact_input(Scene& scene);

}  // namespace efg
