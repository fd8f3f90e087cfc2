// The explicit stages' guard against folded material (operators/CellInversion): a background cell
// corner mirrored (its Jacobian at minus its reference value or below) stops the stage with exit
// 3 naming the cell, the particle, both Jacobians, the step and the time; a corner partly turned
// over is warned about once (a held or sticking corner does so with the right solution).
#pragma once

#include <functional>
#include <string>

#include "drivers/RunState.hpp"
#include "operators/CellInversion.hpp"

namespace efg {

class FoldGuard {
 public:
  FoldGuard(const Model& model, std::string stage) : cells_(model), stage_(std::move(stage)) {}
  /// Checks the cells at the displacements d_overlap (collective); writes the state through
  /// `output` and throws NumericalError at a fold.
  void check(const Tpetra::Vector<>& d_overlap, const RunState& state, long long step,
             const std::function<void(const RunState&)>& output);

 private:
  /// A corner turned over by this share of its reference Jacobian (1: as far over as it stood,
  /// a mirrored corner) stops the stage.
  static constexpr double kFoldedShare = 1.0;
  CellInversion cells_;
  std::string stage_;
  bool warned_ = false;
};

}  // namespace efg
