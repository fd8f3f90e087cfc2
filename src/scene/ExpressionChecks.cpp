#include "scene/ExpressionChecks.hpp"

#include <algorithm>
#include <set>
#include <sstream>

#include "core/Errors.hpp"

namespace efg {
namespace {

class NodeEvaluation {
 public:
  NodeEvaluation(const Scene& scene, const BackgroundMesh& mesh) : mesh_(mesh) {
    times_.push_back(0.0);
    double start = 0.0;
    for (const auto& stage : scene.stages) {
      constexpr int kSamples = 16;  // 17 equally spaced times: halves, quarters, ... included
      for (int k = 1; k <= kSamples; ++k)
        times_.push_back(start + (stage.end_time - start) * k / kSamples);
      start = stage.end_time;
    }
  }

  void check(const ScalarField& f, const std::vector<LocalIndex>& nodes) const {
    if (!f.varies()) return;
    const auto dim = static_cast<std::size_t>(mesh_.dimension);
    for (auto n : nodes) {
      double X[3] = {0, 0, 0};
      for (std::size_t k = 0; k < dim; ++k)
        X[k] = mesh_.coordinates[static_cast<std::size_t>(n) * dim + k];
      if (f.uses_time())
        for (double t : times_) f.at(X, t);
      else
        f.at(X, 0.0);
    }
  }
  void check(const std::vector<ScalarField>& fields, const std::vector<LocalIndex>& nodes) const {
    for (const auto& f : fields) check(f, nodes);
  }

  std::vector<LocalIndex> node_set(const std::string& name) const {
    const auto* set = mesh_.find_node_set(name);
    return set ? set->nodes : std::vector<LocalIndex>{};
  }
  std::vector<LocalIndex> side_set_nodes(const std::string& name) const {
    std::set<LocalIndex> nodes;
    if (const auto* set = mesh_.find_side_set(name))
      for (std::size_t i = 0; i < set->cells.size(); ++i)
        for (auto n :
             mesh_.side_node_indices(static_cast<std::size_t>(set->cells[i]), set->sides[i]))
          nodes.insert(n);
    return {nodes.begin(), nodes.end()};
  }
  // Nodes of the parts selected by `take` (by material, or by name).
  template <class Take>
  std::vector<LocalIndex> part_nodes(const Scene& scene, Take take) const {
    std::set<LocalIndex> nodes;
    for (const auto& part : scene.parts) {
      if (!take(part)) continue;
      for (const auto& b : mesh_.blocks)
        if (std::find(part.blocks.begin(), part.blocks.end(), b.name) != part.blocks.end())
          nodes.insert(b.connectivity.begin(), b.connectivity.end());
    }
    return {nodes.begin(), nodes.end()};
  }
  // A graded modulus must be positive wherever its material is.
  void check_positive(const ScalarField& f, const std::vector<LocalIndex>& nodes) const {
    const auto dim = static_cast<std::size_t>(mesh_.dimension);
    for (auto n : nodes) {
      double X[3] = {0, 0, 0};
      for (std::size_t k = 0; k < dim; ++k)
        X[k] = mesh_.coordinates[static_cast<std::size_t>(n) * dim + k];
      if (const double v = f.at(X, 0.0); !(v > 0)) {
        std::ostringstream o;
        o << f.where << ": expected a positive value everywhere in the material's parts, found '"
          << f.expression->text() << "' = " << v << " at (" << X[0] << ", " << X[1] << ", " << X[2]
          << ")";
        throw InputError(o.str());
      }
    }
  }
  std::vector<LocalIndex> all_nodes() const {
    std::vector<LocalIndex> nodes(mesh_.node_count());
    for (std::size_t n = 0; n < nodes.size(); ++n) nodes[n] = static_cast<LocalIndex>(n);
    return nodes;
  }

 private:
  const BackgroundMesh& mesh_;
  std::vector<double> times_;
};

}  // namespace

void check_expressions_at_nodes(const Scene& scene, const BackgroundMesh& mesh) {
  const NodeEvaluation at(scene, mesh);
  for (const auto& bc : scene.boundary_conditions) {
    const auto nodes = at.node_set(bc.node_set);
    for (const auto& c : bc.components)
      if (c) at.check(*c, nodes);
  }
  for (const auto& load : scene.loads) {
    if (load.type == "traction" || load.type == "pressure")
      at.check(load.value, at.side_set_nodes(load.set));
    else if (load.type == "body_force")
      at.check(load.value, at.part_nodes(scene, [&](const PartSpec& p) {
        return load.parts.empty() ||
               std::find(load.parts.begin(), load.parts.end(), p.name) != load.parts.end();
      }));
  }
  for (const auto& ic : scene.initial_conditions) at.check(ic.value, at.node_set(ic.node_set));
  for (const auto& m : scene.materials)
    if (m.youngs_modulus_field)
      at.check_positive(*m.youngs_modulus_field, at.part_nodes(scene, [&](const PartSpec& p) {
        return p.material == m.name;
      }));
  if (scene.user_solution) {
    const auto nodes = at.all_nodes();
    at.check(scene.user_solution->displacement, nodes);
    at.check(scene.user_solution->stress, nodes);
    at.check(scene.user_solution->body_force, nodes);
  }
}

}  // namespace efg
