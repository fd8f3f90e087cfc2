// The sides of a list of background cells matched by their nodes: which sides two cells of the
// list share (interior) and which only one has (the list's outer boundary). Used for a part's
// boundary (smoothing points, side quadrature, contact), the face neighbours of cells (pressure
// patches) and the outer boundary of a group of cells (a patch's dilatation).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "mesh/BackgroundMesh.hpp"

namespace efg {

struct MatchedSide {
  std::array<LocalIndex, 4> key;  ///< the side's mesh nodes, ascending, padded with -1
  std::uint32_t cell;             ///< index into the cell list
  int side;                       ///< side of that cell (cell-topology order)
};

/// Every side of `cells` (global cell indices), sorted by key, then cell and side: the sides two
/// cells share are neighbours in the list.
std::vector<MatchedSide> matched_sides(const BackgroundMesh& mesh,
                                       const std::vector<std::size_t>& cells);

/// Calls act(first, last) for every run [first, last) of equal keys of `sides` (sorted).
template <class Act>
void for_each_shared_key(const std::vector<MatchedSide>& sides, Act&& act) {
  for (std::size_t k = 0; k < sides.size();) {
    std::size_t end = k + 1;
    while (end < sides.size() && sides[end].key == sides[k].key) ++end;
    act(k, end);
    k = end;
  }
}

/// The sides of `cells` that no other cell of the list shares, as (global cell, side) in global
/// cell and side order.
std::vector<std::pair<std::size_t, int>> outer_sides(const BackgroundMesh& mesh,
                                                     const std::vector<std::size_t>& cells);

/// The cells of the named blocks, ascending global index.
std::vector<std::size_t> cells_of_blocks(const BackgroundMesh& mesh,
                                         const std::vector<std::string>& blocks);

}  // namespace efg
