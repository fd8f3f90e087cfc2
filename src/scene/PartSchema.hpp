// Scene keys of a meshfree part (parts[]: blocks, material, section, shell, formulation; the
// section's basis, kernel, support, integration and its smoothing quadrature).
#pragma once

#include "scene/Schema.hpp"

namespace efg {

schema::SpecPtr part_spec();

}  // namespace efg
