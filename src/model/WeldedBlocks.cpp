#include "model/WeldedBlocks.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numeric>

namespace efg {

BackgroundMesh welded_blocks(const BackgroundMesh& mesh, const std::vector<std::string>& blocks,
                             double tolerance) {
  const auto dim = static_cast<std::size_t>(mesh.dimension);
  const auto x = [&](LocalIndex n, std::size_t k) {
    return mesh.coordinates[static_cast<std::size_t>(n) * dim + k];
  };
  // The blocks' nodes, in order.
  std::vector<char> used(mesh.node_count(), 0);
  for (const auto& name : blocks)
    if (const auto* b = mesh.find_block(name))
      for (auto n : b->connectivity) used[static_cast<std::size_t>(n)] = 1;
  std::vector<LocalIndex> nodes;
  for (std::size_t n = 0; n < used.size(); ++n)
    if (used[n]) nodes.push_back(static_cast<LocalIndex>(n));
  // Their extent: the weld distance is relative to it.
  double extent2 = 0;
  for (std::size_t k = 0; k < dim && !nodes.empty(); ++k) {
    double lo = x(nodes[0], k), hi = lo;
    for (auto n : nodes) {
      lo = std::min(lo, x(n, k));
      hi = std::max(hi, x(n, k));
    }
    extent2 += (hi - lo) * (hi - lo);
  }
  const double weld = tolerance * std::sqrt(extent2);
  // A grid of cells `weld` wide: a node meets only the nodes in its own and the neighbouring
  // cells (O(n); a sweep along x alone would compare every pair in a plane of a structured
  // tool), and joins the first of them within `weld` (in node order).
  std::vector<std::size_t> into(nodes.size());
  std::iota(into.begin(), into.end(), std::size_t{0});
  const double cell = weld > 0 ? weld : 1.0;
  const auto key_of = [&](LocalIndex n, const std::array<long long, 3>& shift) {
    std::array<long long, 3> key{};
    for (std::size_t k = 0; k < dim; ++k)
      key[k] = static_cast<long long>(std::floor(x(n, k) / cell)) + shift[k];
    return key;
  };
  std::map<std::array<long long, 3>, std::vector<std::size_t>> grid;
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    const auto a = nodes[i];
    bool joined = false;
    for (long long dx = -1; dx <= 1 && !joined; ++dx)
      for (long long dy = -1; dy <= 1 && !joined; ++dy)
        for (long long dz = (dim == 3 ? -1 : 0); dz <= (dim == 3 ? 1 : 0) && !joined; ++dz) {
          const auto found = grid.find(key_of(a, {dx, dy, dz}));
          if (found == grid.end()) continue;
          for (auto j : found->second) {
            double d2 = 0;
            for (std::size_t k = 0; k < dim; ++k)
              d2 += (x(a, k) - x(nodes[j], k)) * (x(a, k) - x(nodes[j], k));
            if (d2 <= weld * weld) {
              into[i] = into[j];
              joined = true;
              break;
            }
          }
        }
    grid[key_of(a, {0, 0, 0})].push_back(i);
  }
  // The welded mesh: one node per kept node, the cells on the nodes they were welded into.
  std::vector<LocalIndex> index(mesh.node_count(), -1), kept_index(nodes.size(), -1);
  BackgroundMesh out;
  out.dimension = mesh.dimension;
  out.source = mesh.source;
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    if (into[i] == i) {
      kept_index[i] = static_cast<LocalIndex>(out.node_count());
      for (std::size_t k = 0; k < dim; ++k) out.coordinates.push_back(x(nodes[i], k));
    }
  }
  for (std::size_t i = 0; i < nodes.size(); ++i)
    index[static_cast<std::size_t>(nodes[i])] = kept_index[into[i]];
  for (const auto& name : blocks)
    if (const auto* b = mesh.find_block(name)) {
      auto copy = *b;
      for (auto& n : copy.connectivity) n = index[static_cast<std::size_t>(n)];
      out.blocks.push_back(std::move(copy));
    }
  return out;
}

}  // namespace efg
