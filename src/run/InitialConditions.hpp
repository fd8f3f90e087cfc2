// Initial velocities and displacements on node sets, set on the generalized dofs of the sets'
// particles (exact for uniform values over a whole part, where sum_I phi_I = 1 makes generalized
// and physical values equal).
#pragma once

#include "drivers/RunState.hpp"
#include "model/Model.hpp"

namespace efg {

void apply_initial_conditions(const Model& model, RunState& state);

}  // namespace efg
