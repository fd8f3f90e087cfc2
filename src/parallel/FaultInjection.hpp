// A test hook that raises an error on one rank at a named phase of a run, to prove that every
// rank then stops with the same exit code (tests/cli: fault injection). Off unless the
// environment names a phase:
//   EFG_FAULT=PHASE:RANK[:EXIT]   e.g. EFG_FAULT=output:1 or EFG_FAULT=loads:0:2
// raises, every time rank RANK reaches fault_point(PHASE) (a defect, not a passing glitch: a
// Newton cutback meets it again), a NumericalError (EXIT 3, the default) or an InputError
// (EXIT 2). The phases are listed in kFaultPhases.
#pragma once

#include <array>
#include <string_view>

namespace efg {

/// The phases a run passes through, each with a fault point where its real errors arise.
inline constexpr std::array<std::string_view, 11> kFaultPhases = {
    "mesh",            // reading or generating the mesh (root and slices)
    "discretization",  // shape functions and integration points
    "operators",       // the model's operators (supports, contact pairs, stiffness graph)
    "initial_state",   // reading a restart record
    "stable_step",     // the explicit stable time step estimate
    "loads",           // evaluating the external loads (expressions of x and t)
    "contact",         // contact forces
    "internal_force",  // the internal force (explicit steps, stable step estimates)
    "newton",          // an implicit residual
    "output",          // writing a record
    "report",          // the run report at the end
};

/// Throws the injected error when EFG_FAULT names `phase` and this rank (see above).
void fault_point(std::string_view phase);

}  // namespace efg
