// Scene keys of a stage (stages[]: the driver and its own keys, implicit or explicit; the
// scene reader and the solver settings check read them).
#pragma once

#include "scene/Schema.hpp"

namespace efg {

schema::SpecPtr stage_spec();

}  // namespace efg
