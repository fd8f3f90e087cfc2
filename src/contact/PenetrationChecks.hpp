// What the explicit contact with rigid bodies watches besides its forces (contact/PenaltyContact),
// and its messages:
// - depth: the deepest particle's -g / h_J, h_J its boundary spacing: a penalty contact always
//   penetrates (delta / h = p / (penalty_scale K) under a pressure p, ContactStiffness.hpp), and
//   the user sees how far;
// - tunnelling: a penalty acts on the gap at the step's end only. A body that moves a distance s
//   against a particle in one step can carry a particle from in front of its surface to behind
//   its far side, or out of reach of its closest-point normal, with no force at any evaluation
//   (a disc at 1e3 crossed a block in one step, force 0, exit 0). Every point the body swept over
//   the step lies within s of it now (the swept volume is the body grown by the step's
//   translation), so a particle closer than s + h is near; s > kTunnellingFraction h there stops
//   the run (exit 3) rather than let it pass silently;
// - initial overlap: a particle inside the body at the run's start would be shot out by the
//   full penalty of its depth at once (energy from nowhere: 3.5x measured).
#pragma once

#include <string>

namespace efg::contact {

/// Largest relative travel per step against a near part, as a fraction of its spacing.
constexpr double kTunnellingFraction = 0.5;
/// A particle deeper than this fraction of its spacing at the start is inside the body (a body
/// set exactly on a surface has gap 0 up to round-off).
constexpr double kInitialDepthTolerance = 1e-9;

/// "rigid body 'X' moved Y per step against part 'P' (particle spacing Z) ...".
std::string tunnelling_message(const std::string& body, const std::string& part, double travel,
                               double spacing);

/// "contact 'c' (contacts[i]): N particles start inside rigid body 'b'; the deepest, particle P
/// (X = (...)), by D (F % of its spacing h) ...".
std::string initial_penetration_message(const std::string& contact, long index,
                                        const std::string& body, long long count,
                                        long long particle, const double* X, int dim, double depth,
                                        double spacing);

/// "contact 'c': a particle is D % of its spacing deep in rigid body 'b' at t = ...".
std::string penetration_warning(const std::string& contact, const std::string& body,
                                double fraction, double threshold, double time);

}  // namespace efg::contact
