// Cross-checks of j2_plasticity materials against the rest of a scene, beyond what the schema
// says of each key: the hardening curve (named, starting at (0, yield_stress), strain
// increasing, stress not decreasing, within the law's capacity), one hardening description,
// and the parts and conditions the law is not built for yet.
#pragma once

#include "scene/Scene.hpp"

namespace efg {

/// Throws InputError at file:line:col and key path for the first problem.
void check_plasticity_input(const Scene& scene);

}  // namespace efg
