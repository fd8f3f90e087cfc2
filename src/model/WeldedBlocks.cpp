#include "model/WeldedBlocks.hpp"

#include <algorithm>
#include <cmath>
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
  // Sorted along x, each node meets only the ones within `weld` of it in x (a sweep: O(n log n)
  // for a tool's mesh); a node joins the first (lowest index) of those it meets.
  std::vector<std::size_t> order(nodes.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return x(nodes[a], 0) < x(nodes[b], 0); });
  std::vector<std::size_t> into(nodes.size());
  std::iota(into.begin(), into.end(), std::size_t{0});
  for (std::size_t i = 0; i < order.size(); ++i)
    for (std::size_t j = i + 1; j < order.size(); ++j) {
      const auto a = nodes[order[i]], b = nodes[order[j]];
      if (x(b, 0) - x(a, 0) > weld) break;
      double d2 = 0;
      for (std::size_t k = 0; k < dim; ++k) d2 += (x(a, k) - x(b, k)) * (x(a, k) - x(b, k));
      if (d2 > weld * weld) continue;
      const auto low = std::min(into[order[i]], into[order[j]]);
      into[order[i]] = into[order[j]] = low;
    }
  // The welded mesh: one node per kept node, the cells on the nodes they were welded into.
  for (std::size_t i = 0; i < into.size(); ++i) into[i] = into[into[i]];  // chains of welds
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
