#include "operators/ExternalLoads.hpp"

#include <algorithm>

#include "core/Errors.hpp"
#include "discretization/ShapeFunctions.hpp"
#include "model/NodeSetSize.hpp"
#include "operators/SideQuadrature.hpp"
#include "parallel/Collective.hpp"
#include "parallel/FaultInjection.hpp"

namespace efg {

int part_of_block(const Scene& scene, const std::string& name) {
  for (std::size_t p = 0; p < scene.parts.size(); ++p)
    if (std::find(scene.parts[p].blocks.begin(), scene.parts[p].blocks.end(), name) !=
        scene.parts[p].blocks.end())
      return static_cast<int>(p);
  return -1;
}

namespace {

using Points = ExternalLoads::Points;

void add_point(Points& pts, std::size_t part, const double* x, int dim,
               const std::array<double, 3>& normal, double weight) {
  std::array<double, 3> p{0, 0, 0};
  std::copy(x, x + dim, p.begin());
  pts.x.push_back(p);
  pts.normal.push_back(normal);
  pts.weight.push_back(weight);
  pts.part.push_back(part);
}

// The rows phi_I(x_p) of free points (sides, nodes), part by part, in overlap node numbering.
void evaluate_rows(const Model& model, const SolidOperator& op, Points& pts) {
  const auto udim = static_cast<std::size_t>(model.mesh.dimension);
  pts.rows.offsets.assign(1, 0);
  std::vector<std::vector<std::pair<LocalIndex, double>>> row(pts.weight.size());
  for (std::size_t p = 0; p < model.parts.size(); ++p) {
    std::vector<std::size_t> mine;
    std::vector<double> x;
    for (std::size_t q = 0; q < pts.weight.size(); ++q)
      if (pts.part[q] == p) {
        mine.push_back(q);
        x.insert(x.end(), pts.x[q].begin(), pts.x[q].begin() + static_cast<std::ptrdiff_t>(udim));
      }
    if (mine.empty()) continue;
    const auto v =
        evaluate_shape_functions(model.parts[p].cloud, x.data(), mine.size(), false,
                                 [](std::size_t q) { return "load point " + std::to_string(q); });
    for (std::size_t i = 0; i < mine.size(); ++i)
      for (auto k = v.neighbors.offsets[i]; k < v.neighbors.offsets[i + 1]; ++k)
        row[mine[i]].emplace_back(
            op.overlap_node(p)[static_cast<std::size_t>(v.neighbors.particles[k])], v.phi[k]);
  }
  for (const auto& r : row) {
    for (const auto& [node, phi] : r) {
      pts.rows.particles.push_back(node);
      pts.rows.values.push_back(phi);
    }
    pts.rows.offsets.push_back(pts.rows.particles.size());
  }
}

// Tractions and pressures: the SCNI boundary points of the set's owned sides.
Points surface_points(const Model& model, const LoadSpec& spec) {
  const auto& mesh = model.mesh;
  const int dim = mesh.dimension;
  Points pts;
  const auto* set = mesh.find_side_set(spec.set);
  for (std::size_t i = 0; i < set->cells.size(); ++i) {
    const auto cell = static_cast<std::size_t>(set->cells[i]);
    const auto nodes = mesh.side_node_indices(cell, set->sides[i]);
    const auto first = *std::min_element(nodes.begin(), nodes.end());
    if (model.partition.owner[static_cast<std::size_t>(first)] != model.partition.rank) continue;
    const int part = part_of_block(model.scene, mesh.locate_cell(cell).first->name);
    if (part < 0) continue;
    const double thickness =
        dim == 2 ? model.scene.parts[static_cast<std::size_t>(part)].thickness : 1.0;
    for (const auto& q : side_quadrature(mesh, cell, set->sides[i]))
      add_point(pts, static_cast<std::size_t>(part), q.x.data(), dim, q.normal,
                q.weight * thickness);
  }
  return pts;
}

// A force on a node set, shared equally by its nodes (at each owned particle of the set).
Points nodal_points(const Model& model, const LoadSpec& spec) {
  Points pts;
  const auto* set = model.mesh.find_node_set(spec.set);
  // (a rank's part of a mesh read in slices holds part of the set: its size over the ranks)
  const double share =
      1.0 / static_cast<double>(model.mesh.is_part() ? owned_entries_over_ranks(model, *set)
                                                     : set->nodes.size());
  for (auto node : set->nodes) {
    if (model.partition.owner[static_cast<std::size_t>(node)] != model.partition.rank) continue;
    for (std::size_t p = 0; p < model.parts.size(); ++p) {
      const auto& c = model.parts[p].cloud;
      const auto end = c.mesh_node.begin() + static_cast<std::ptrdiff_t>(c.owned_count);
      const auto it = std::find(c.mesh_node.begin(), end, node);
      if (it == end) continue;
      add_point(pts, p, c.x(static_cast<std::size_t>(it - c.mesh_node.begin())),
                model.mesh.dimension, {0, 0, 0}, share);
    }
  }
  return pts;
}

// A body force over the named parts (all when none), at the parts' integration points (their
// rows of phi_I exist already).
Points body_points(const Model& model, const SolidOperator& op, const LoadSpec& spec) {
  const int dim = model.mesh.dimension;
  Points pts;
  pts.rows.offsets.assign(1, 0);
  for (std::size_t p = 0; p < model.parts.size(); ++p) {
    const auto& part = *model.parts[p].part;
    if (!spec.parts.empty() &&
        std::find(spec.parts.begin(), spec.parts.end(), part.name) == spec.parts.end())
      continue;
    const auto& ip = model.parts[p].points;
    const double thickness = dim == 2 ? part.thickness : 1.0;
    for (std::size_t q = 0; q < ip.size(); ++q) {
      add_point(pts, p, &ip.x[q * static_cast<std::size_t>(dim)], dim, {0, 0, 0},
                ip.weight[q] * thickness);
      for (auto k = ip.values.offsets[q]; k < ip.values.offsets[q + 1]; ++k) {
        pts.rows.particles.push_back(
            op.overlap_node(p)[static_cast<std::size_t>(ip.values.particles[k])]);
        pts.rows.values.push_back(ip.values.values[k]);
      }
      pts.rows.offsets.push_back(pts.rows.particles.size());
    }
  }
  return pts;
}

// The load per unit weight at point q and time t.
std::array<double, 3> load_value(const LoadSpec& spec, const ExactSolution* exact, int dim,
                                 const Points& pts, std::size_t q, double t) {
  std::array<double, 3> value{0, 0, 0};
  const double* x = pts.x[q].data();
  if (spec.type == "pressure") {
    const double p = spec.value[0].at(x, t);
    for (std::size_t d = 0; d < 3; ++d) value[d] = -p * pts.normal[q][d];
  } else if (spec.from_exact && spec.type == "traction") {
    double P[3][3];
    exact->nominal_stress(x, P);
    for (std::size_t a = 0; a < 3; ++a)
      for (std::size_t b = 0; b < 3; ++b) value[a] += P[a][b] * pts.normal[q][b];
  } else if (spec.from_exact) {
    if (exact->body_force) exact->body_force(x, value.data());
  } else {
    for (std::size_t d = 0; d < static_cast<std::size_t>(dim); ++d)
      value[d] = spec.value[d].at(x, t);
  }
  return value;
}

// f_overlap += scale * sum over points of phi_I(x_p) value(x_p, t) w_p.
void scatter(const LoadSpec& spec, const ExactSolution* exact, int dim, const Points& pts, double t,
             double scale, Vector& f_overlap) {
  fault_point("loads");
  auto f = f_overlap.getLocalViewHost(Tpetra::Access::ReadWrite);
  const auto udim = static_cast<std::size_t>(dim);
  for (std::size_t q = 0; q < pts.weight.size(); ++q) {
    auto value = load_value(spec, exact, dim, pts, q, t);
    for (auto& v : value) v *= scale * pts.weight[q];
    for (auto k = pts.rows.offsets[q]; k < pts.rows.offsets[q + 1]; ++k) {
      const auto node = static_cast<std::size_t>(pts.rows.particles[k]);
      for (std::size_t i = 0; i < udim; ++i) f(node * udim + i, 0) += pts.rows.values[k] * value[i];
    }
  }
}

bool varies_in_time(const LoadSpec& spec) {
  return std::any_of(spec.value.begin(), spec.value.end(),
                     [](const ScalarField& v) { return v.uses_time(); });
}

}  // namespace

ExternalLoads::ExternalLoads(const Model& model, const SolidOperator& op,
                             const ExactSolution* exact)
    : exact_(exact),
      dim_(model.mesh.dimension),
      overlap_(model.maps.overlap_dofs),
      owned_(model.maps.owned_dofs),
      to_owned_(Teuchos::rcp(new Tpetra::Export<>(overlap_, owned_))) {
  for (const auto& spec : model.scene.loads) {
    Load load{&spec, Teuchos::null, {}};
    if (spec.type == "body_force") {
      load.points = body_points(model, op, spec);
    } else {
      load.points =
          spec.type == "nodal_force" ? nodal_points(model, spec) : surface_points(model, spec);
      evaluate_rows(model, op, load.points);
    }
    if (!varies_in_time(spec)) {  // assembled once for a unit factor; the points are dropped
      Vector f_overlap(overlap_);
      scatter(spec, exact_, dim_, load.points, 0.0, 1.0, f_overlap);
      load.force = Teuchos::rcp(new Vector(owned_));
      load.force->doExport(f_overlap, *to_owned_, Tpetra::ADD);
      load.points = Points{};
    } else if (timed_overlap_.is_null()) {  // work vectors of the per-assembly loads, once
      timed_overlap_ = Teuchos::rcp(new Vector(overlap_));
      timed_owned_ = Teuchos::rcp(new Vector(owned_));
    }
    loads_.push_back(std::move(load));
  }
}

void ExternalLoads::assemble(const LoadFactor& factor, Vector& f_owned) const {
  f_owned.putScalar(0.0);
  for (const auto& l : loads_)
    if (l.spec->stages.includes(factor.stage()) && !l.force.is_null())
      f_owned.update(factor(l.spec->curve), *l.force, 1.0);
  if (!timed_overlap_.is_null()) {
    // An expression may be finite at the scene check's sample times and not at a time the run
    // reaches (1/(t - 0.4) at a load step ending at 0.4). Only the ranks holding the loaded
    // points find it: every rank learns of it here, before the export where the others would
    // wait for them forever.
    run_collectively(owned_->getComm(), [&] {
      timed_overlap_->putScalar(0.0);
      for (const auto& l : loads_) {
        if (!l.spec->stages.includes(factor.stage()) || !l.force.is_null()) continue;
        // An expression of t is the value at that time: no default ramp without a curve.
        const double f = l.spec->curve.empty() ? 1.0 : factor(l.spec->curve);
        scatter(*l.spec, exact_, dim_, l.points, factor.time(), f, *timed_overlap_);
      }
    });
    timed_owned_->putScalar(0.0);  // as a fresh vector: ADD sums every rank's share
    timed_owned_->doExport(*timed_overlap_, *to_owned_, Tpetra::ADD);
    f_owned.update(1.0, *timed_owned_, 1.0);
  }
}

bool ExternalLoads::constant_in(const std::string& stage) const {
  for (const auto& l : loads_)
    if (l.spec->stages.includes(stage) && (l.force.is_null() || !l.spec->curve.empty()))
      return false;
  return true;
}

std::size_t ExternalLoads::timed_point_count() const {
  std::size_t n = 0;
  for (const auto& l : loads_) n += l.points.weight.size();
  return n;
}

}  // namespace efg
