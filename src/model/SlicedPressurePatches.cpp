#include "model/SlicedPressurePatches.hpp"

#include <algorithm>

#include "parallel/Exchange.hpp"
#include "parallel/SliceLookup.hpp"

namespace efg {

SlicedPatches patches_from_slices(const CommPtr& comm, const Scene& scene, const MeshSlice& slice) {
  SlicedPatches out;
  out.part.resize(scene.parts.size());
  const auto dim = static_cast<std::size_t>(slice.dimension);
  for (std::size_t p = 0; p < scene.parts.size(); ++p) {
    const auto& part = scene.parts[p];
    if (part.formulation != PartFormulation::mixed_up ||
        part.pressure_cells != PressureCellChoice::patch)
      continue;
    // The part's blocks whole, in file order (the slices' ranges follow the file's cells).
    std::vector<const BlockSlice*> blocks;
    std::vector<std::vector<GlobalIndex>> connectivity;
    for (const auto& b : slice.blocks)
      if (std::find(part.blocks.begin(), part.blocks.end(), b.name) != part.blocks.end()) {
        blocks.push_back(&b);
        connectivity.push_back(all_gather(comm, b.connectivity));
      }
    // Their nodes numbered compactly in the whole mesh's order, so that the greedy choice in node
    // order visits them as on the whole mesh.
    std::vector<GlobalIndex> ids;
    for (const auto& c : connectivity) ids.insert(ids.end(), c.begin(), c.end());
    std::sort(ids.begin(), ids.end());
    ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
    BackgroundMesh whole;
    whole.dimension = slice.dimension;
    whole.coordinates = fetch_from_slices(comm, slice.node_count, dim, slice.coordinates, ids);
    for (std::size_t b = 0; b < blocks.size(); ++b) {
      ElementBlock block;
      block.name = blocks[b]->name;
      block.id = blocks[b]->id;
      block.type = blocks[b]->type;
      block.connectivity.reserve(connectivity[b].size());
      for (auto g : connectivity[b])
        block.connectivity.push_back(
            static_cast<LocalIndex>(std::lower_bound(ids.begin(), ids.end(), g) - ids.begin()));
      connectivity[b] = {};
      whole.blocks.push_back(std::move(block));
    }
    auto groups = pressure_cells(whole, part);
    out.largest_diameter = std::max(out.largest_diameter, largest_group_diameter(whole, groups));
    // The cells' whole-mesh indices: block b's cells follow its first cell.
    std::vector<std::size_t> start{0};
    for (const auto& b : whole.blocks) start.push_back(start.back() + b.cell_count());
    for (auto& c : groups.cells) {
      const auto b = static_cast<std::size_t>(std::upper_bound(start.begin(), start.end(), c) -
                                              start.begin()) -
                     1;
      c = static_cast<std::size_t>(blocks[b]->first_cell) + (c - start[b]);
    }
    groups.group.clear();
    out.part[p] = std::move(groups);
  }
  return out;
}

}  // namespace efg
