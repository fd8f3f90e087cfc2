// The particles inside a rigid body at the run's start (PenaltyContact::start; the why in
// contact/PenetrationChecks.hpp): counted per contact, the deepest named the same on every
// rank; initial_penetration stop throws, ignore keeps each one's depth as its allowance, push
// leaves them to the penalty.
#include <Teuchos_CommHelpers.hpp>

#include <climits>
#include <sstream>

#include "contact/PenaltyContact.hpp"
#include "contact/PenetrationChecks.hpp"
#include "core/Errors.hpp"
#include "core/Log.hpp"

namespace efg {

void PenaltyContact::initial_overlaps(const std::vector<RigidBodyState>& bodies) {
  // Particles inside a body at the run's start (contacts; rigid walls as they always were).
  for (auto& pair : pairs_) {
    if (pair.contact < 0 || pair.initial == "push") continue;
    const auto& body = bodies[pair.body];
    const Candidate* worst = nullptr;
    double deepest = 0, count = 0;
    for (auto& c : pair.candidates) {
      const auto near =
          contact::proximity_of_body(bodies_.shape(pair.body), c.x_old.data(),
                                     body.displacement.data(), body.rotation[2], body.orientation);
      if (!(-near.gap > contact::kInitialDepthTolerance * c.spacing)) continue;
      count += 1;
      if (pair.initial == "ignore") c.allowance = c.allowance_new = -near.gap;
      if (-near.gap / c.spacing > deepest) {
        deepest = -near.gap / c.spacing;
        worst = &c;
      }
    }
    double mine[2] = {deepest, count}, all[2] = {0, 0};
    Teuchos::reduceAll(*comm_, Teuchos::REDUCE_MAX, 1, mine, all);
    Teuchos::reduceAll(*comm_, Teuchos::REDUCE_SUM, 1, mine + 1, all + 1);
    if (all[1] == 0) continue;
    const auto& spec = model_.scene.contacts[static_cast<std::size_t>(pair.contact)];
    if (pair.initial == "ignore") {
      std::ostringstream o;
      o << "contact '" << spec.name << "': " << static_cast<long long>(all[1])
        << " particles start inside rigid body '" << spec.rigid_body << "' (the deepest "
        << 100.0 * all[0] << " % of its spacing); initial_penetration: ignore takes their "
        << "initial depth as zero";
      Log::info(o.str());
      continue;
    }
    // The deepest particle, named the same on every rank (the lowest id among equals).
    long long id = worst && deepest == all[0] ? worst->particle : LLONG_MAX, first = 0;
    Teuchos::reduceAll(*comm_, Teuchos::REDUCE_MIN, id, Teuchos::outArg(first));
    double where[5] = {0, 0, 0, 0, 0}, at[5] = {0, 0, 0, 0, 0};  // X, depth, spacing
    if (worst && worst->particle == first) {
      for (std::size_t k = 0; k < 3; ++k) where[k] = worst->row.X[k];
      where[3] = all[0] * worst->spacing;
      where[4] = worst->spacing;
    }
    Teuchos::reduceAll(*comm_, Teuchos::REDUCE_SUM, 5, where, at);
    throw NumericalError(contact::initial_penetration_message(
        spec.name, pair.contact, spec.rigid_body, static_cast<long long>(all[1]), first, at, dim_,
        at[3], at[4]));
  }
}

}  // namespace efg
