// Scene keys of rigid bodies and contacts (the schema of rigid_bodies[] and contacts[];
// scene/ContactInput reads and cross-checks them).
#pragma once

#include "scene/Schema.hpp"

namespace efg {

schema::SpecPtr rigid_body_spec();
schema::SpecPtr contact_spec();

}  // namespace efg
