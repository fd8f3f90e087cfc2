#include "shells/ShellThickness.hpp"

#include <cmath>
#include <sstream>
#include <string>

#include "core/Errors.hpp"

namespace efg {

std::vector<double> shell_particle_thickness(const Model& model, std::size_t part) {
  const auto& d = model.parts[part];
  const auto& spec = *d.part;
  const auto& mesh = model.mesh;
  const auto& nodes = d.cloud.mesh_node;
  std::vector<double> t(nodes.size(), spec.thickness);  // a plane-stress part's own thickness
  std::string where;
  if (spec.shell && spec.shell->thickness) {
    const auto& field = *spec.shell->thickness;
    where = field.where;
    for (std::size_t i = 0; i < nodes.size(); ++i) {
      const auto n = static_cast<std::size_t>(nodes[i]);
      // a surface read in 3D: its own positions (x, y, z), else the mesh's (x, y, 0)
      const double p[3] = {
          mesh.surface.empty() ? mesh.coordinates[2 * n] : mesh.surface[3 * n],
          mesh.surface.empty() ? mesh.coordinates[2 * n + 1] : mesh.surface[3 * n + 1],
          mesh.surface.empty() ? 0.0 : mesh.surface[3 * n + 2]};
      t[i] = field.at(p, 0.0);
    }
  } else if (spec.shell) {
    std::size_t index = 0;
    while (index + 1 < model.scene.parts.size() && model.scene.parts[index].name != spec.name)
      ++index;
    where = model.scene.file + ": parts[" + std::to_string(index) + "].shell.thickness";
    // the mean of each node's cells' attributes over the part's blocks
    std::vector<double> sum(mesh.node_count(), 0.0), count(sum.size(), 0.0);
    for (const auto& name : spec.blocks) {
      const auto* block = mesh.find_block(name);
      if (!block) continue;  // (the scene check names a missing block)
      if (block->thickness.empty())
        throw InputError(where + ": not given, and mesh block '" + name + "' of part '" +
                         spec.name +
                         "' carries no thickness attribute; expected a thickness here, or a "
                         "thickness attribute per cell of every block of the part");
      const std::size_t per_cell = static_cast<std::size_t>(cell_node_count(block->type));
      for (std::size_t c = 0; c < block->cell_count(); ++c)
        for (std::size_t k = 0; k < per_cell; ++k) {
          const auto n = static_cast<std::size_t>(block->connectivity[c * per_cell + k]);
          sum[n] += block->thickness[c];
          count[n] += 1;
        }
    }
    for (std::size_t i = 0; i < nodes.size(); ++i) {
      const auto n = static_cast<std::size_t>(nodes[i]);
      t[i] = count[n] > 0 ? sum[n] / count[n] : 0.0;
    }
  }
  for (std::size_t i = 0; i < t.size(); ++i)
    if (!(t[i] > 0) || !std::isfinite(t[i])) {
      std::ostringstream o;
      o << where << ": the thickness at particle " << nodes[i] + 1 << " of part '" << spec.name
        << "' is " << t[i] << "; expected a finite value > 0";
      throw InputError(o.str());
    }
  return t;
}

}  // namespace efg
