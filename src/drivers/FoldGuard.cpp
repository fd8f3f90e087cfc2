#include "drivers/FoldGuard.hpp"

#include <sstream>

#include "core/Errors.hpp"
#include "core/Log.hpp"

namespace efg {

void FoldGuard::check(const Tpetra::Vector<>& d_overlap, const RunState& state, long long step,
                      const std::function<void(const RunState&)>& output) {
  const auto folded = cells_.most_inverted(d_overlap);
  if (!folded) return;
  std::ostringstream where;
  where << "background cell " << folded->cell << " of part '" << folded->part
        << "' turned inside out at particle " << folded->particle << " (its corner Jacobian "
        << folded->current_det << ", " << folded->reference_det << " in the reference) at step "
        << step << ", t = " << state.time;
  // A corner turned over as far as it stood (mirrored) or more: particles passed each other.
  if (folded->ratio() <= -kFoldedShare) {
    // The folded state is written when the record takes it; a small-strain part's own check
    // refuses it (every rank alike: its check is collective), and the results end before.
    bool written = true;
    try {
      output(state);
    } catch (const NumericalError&) {
      written = false;
    }
    throw NumericalError("stage '" + stage_ + "': particles passed each other: " + where.str() +
                         ": the material folded through itself (a crush the particles cannot "
                         "represent, or a contact that let a part through); " +
                         (written ? "the last state is in the results"
                                  : "the results end at the last record before"));
  }
  if (!warned_)
    Log::warning("stage '" + stage_ + "': " + where.str() +
                 ": a corner slightly turned over (a held or sticking corner's particles "
                 "overtaking each other; the stage stops when one is mirrored, its Jacobian at "
                 "minus its reference value; docs/explicit.md, \"Guards\")");
  warned_ = true;
}

}  // namespace efg
