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

/// The share of a contact in the central-difference stability condition, P + 2 D, with P the
/// omega^2 dt^2 of its spring and D = c dt / m of its damper for the motion they act on (a
/// particle on a rigid body; two facing particles of equal mass, reduced mass m / 2, between
/// deformable parts, two-way with two springs and dampers): with the lagged damping velocity the
/// condition is omega_el^2 dt^2 + P + 2 D <= 4, so the stable step falls by
/// sqrt(1 - (P + 2 D) / 4). Rigid: P = penalty, D = 2 damping sqrt(penalty); between parts
/// one-way P = 2 penalty, D = 2 sqrt(2) damping sqrt(penalty); two-way P = 4 penalty,
/// D = 4 damping sqrt(penalty) (the dampers of SurfaceContact and PenaltyContact).
double contact_stability_share(const ContactSpec& contact);

/// Fills scene.rigid_bodies and scene.contacts from scene.resolved; throws InputError at
/// file:line:col and key path for the first problem.
void read_contact_input(Scene& scene);

}  // namespace efg
