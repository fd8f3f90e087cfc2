#include "run/ShellStageInputs.hpp"

#include "core/Errors.hpp"
#include "discretization/ShapeFunctions.hpp"
#include "model/Curves.hpp"
#include "model/PointOwner.hpp"
#include "shells/ShellReference.hpp"

namespace efg {
namespace {
constexpr int nd = shell_dofs_per_node;
}

std::vector<ShellSupport> shell_supports_at(const Scene& scene, const std::string& stage,
                                            double time, double ramp) {
  const auto factor = curve_factor(scene, time, ramp, stage);
  std::vector<ShellSupport> out;
  for (std::size_t i = 0; i < scene.boundary_conditions.size(); ++i) {
    const auto& bc = scene.boundary_conditions[i];
    if (!bc.stages.includes(stage)) continue;
    ShellSupport s;
    s.node_set = bc.node_set;
    s.key = "boundary_conditions[" + std::to_string(i) + "]";
    s.method = bc.method == "nitsche"   ? ShellMethod::nitsche
               : bc.method == "penalty" ? ShellMethod::penalty
                                        : ShellMethod::transformation;
    s.alpha = bc.penalty.value_or(0.0);
    const double scale = factor(bc.curve);
    for (std::size_t c = 0; c < nd; ++c) {
      const auto& field = c < 3 ? bc.components[c] : bc.rotations[c - 3];
      if (field)
        s.value[c] = [f = *field, scale, time](const double* x) {
          const double p[3] = {x[0], x[1], 0.0};
          return scale * f.at(p, time);
        };
    }
    out.push_back(s);
  }
  return out;
}

bool shell_supports_move(const Scene& scene, const std::string& stage) {
  for (const auto& bc : scene.boundary_conditions) {
    if (!bc.stages.includes(stage)) continue;
    if (!bc.curve.empty()) return true;
    for (std::size_t c = 0; c < nd; ++c) {
      const auto& field = c < 3 ? bc.components[c] : bc.rotations[c - 3];
      if (field && field->uses_time()) return true;
    }
  }
  return false;
}

bool has_follower_pressure(const Scene& scene, const std::string& stage) {
  for (const auto& l : scene.loads)
    if (l.type == "shell_pressure" && l.follower && l.stages.includes(stage)) return true;
  return false;
}

FlatShellOperator::Pressure shell_pressure_at(const Model& model, const std::string& stage,
                                              double time, double ramp, bool follower) {
  const auto& scene = model.scene;
  const auto factor = curve_factor(scene, time, ramp, stage);
  std::vector<std::pair<const LoadSpec*, double>> loads;
  for (const auto& l : scene.loads)
    if (l.type == "shell_pressure" && l.follower == follower && l.stages.includes(stage))
      loads.emplace_back(&l, factor(l.curve));
  return [&model, loads, time](std::size_t part, const double* x) {
    double q = 0;
    for (const auto& [l, scale] : loads) {
      bool applies = l->parts.empty();
      for (const auto& name : l->parts) applies = applies || name == model.parts[part].part->name;
      if (applies) q += scale * l->value.front().at(x, time);
    }
    return q;
  };
}

ShellLineAndPointLoads::ShellLineAndPointLoads(const Model& model, const FlatShellOperator& op,
                                               const std::string& stage)
    : model_(model), op_(op), stage_(stage) {
  for (const auto& l : model.scene.loads) {
    if (l.type != "shell_edge_load" || !l.stages.includes(stage)) continue;
    long long sides = 0;
    auto points = shell_edge_points(model, l.set, &sides);
    for (auto& p : points)  // per unit length of the surface (a curved reference's map)
      p.length *= edge_stretch(model, p.part, p.x.data(), p.normal.data());
    loads_.emplace_back(&l, std::move(points));
    if (sides == 0)
      throw InputError(model.scene.file + ": load '" + l.name + "': node set '" + l.set +
                       "' covers no edge of a shell part");
  }
  for (const auto& l : model.scene.loads) {
    if (l.type != "shell_point_load" || !l.stages.includes(stage)) continue;
    PointLoad p{&l, {}, {}};
    const int part = evaluating_part(model, l.point.data());
    if (part >= 0) {
      const auto& cloud = model.parts[static_cast<std::size_t>(part)].cloud;
      const auto v = evaluate_shape_functions(cloud, l.point.data(), 1, false, [&](std::size_t) {
        return "load '" + l.name + "' (shell_point_load)";
      });
      for (auto k = v.neighbors.offsets[0]; k < v.neighbors.offsets[1]; ++k) {
        const auto node = cloud.mesh_node[static_cast<std::size_t>(v.neighbors.particles[k])];
        p.node.push_back(op.maps().overlap_nodes->getLocalElement(global_node_id(model, node)));
        p.phi.push_back(v.phi[k]);
      }
    }
    points_.push_back(std::move(p));
  }
}

void ShellLineAndPointLoads::add(double time, double ramp,
                                 FlatShellOperator::Vector& f_owned) const {
  if (empty()) return;
  const auto factor = curve_factor(model_.scene, time, ramp, stage_);
  FlatShellOperator::Vector f_overlap(op_.maps().overlap_dofs);
  {
    auto f = f_overlap.getLocalViewHost(Tpetra::Access::ReadWrite);
    const auto& overlap = *op_.maps().overlap_nodes;
    for (const auto& [load, points] : loads_) {
      const double scale = factor(load->curve);
      for (const auto& p : points) {
        const double x[3] = {p.x[0], p.x[1], 0.0};
        double q[nd];
        for (std::size_t c = 0; c < nd; ++c) q[c] = scale * load->value[c].at(x, time);
        for (std::size_t a = 0; a < p.node.size(); ++a) {
          const auto lid =
              static_cast<std::size_t>(overlap.getLocalElement(global_node_id(model_, p.node[a])));
          for (std::size_t c = 0; c < nd; ++c) f(lid * nd + c, 0) += p.length * p.phi[a] * q[c];
        }
      }
    }
    for (const auto& p : points_) {
      if (p.node.empty()) continue;
      const double scale = factor(p.load->curve);
      double q[nd];
      for (std::size_t c = 0; c < nd; ++c)
        q[c] = scale * p.load->value[c].at(p.load->point.data(), time);
      for (std::size_t a = 0; a < p.node.size(); ++a)
        for (std::size_t c = 0; c < nd; ++c)
          f(static_cast<std::size_t>(p.node[a]) * nd + c, 0) += p.phi[a] * q[c];
    }
  }
  op_.add_overlap(f_overlap, f_owned);
}

}  // namespace efg
