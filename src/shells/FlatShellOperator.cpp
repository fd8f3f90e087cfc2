#include "shells/FlatShellOperator.hpp"

#include <Teuchos_CommHelpers.hpp>
#include <Tpetra_Import.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <utility>

#include "core/Errors.hpp"
#include "discretization/ShapeFunctions.hpp"
#include "model/MaterialLaws.hpp"
#include "operators/CouplingGraph.hpp"
#include "scene/ShellReferenceMap.hpp"
#include "shells/FlatShellPointLaw.hpp"
#include "shells/ShellConstraints.hpp"
#include "shells/ShellReference.hpp"
#include "shells/ShellSpacing.hpp"
#include "shells/ShellThickness.hpp"

namespace efg {
namespace {

constexpr int nd = shell_dofs_per_node;

}  // namespace

FlatShellOperator::FlatShellOperator(const Model& model, int thickness_points,
                                     double shear_stabilization)
    : model_(model),
      maps_(
          make_dof_maps(model.maps.owned_nodes->getComm(), model.partition, nd, model.mesh.global)),
      importer_(Teuchos::rcp(new Tpetra::Import<>(maps_.owned_dofs, maps_.overlap_dofs))),
      exporter_(Teuchos::rcp(new Tpetra::Export<>(maps_.overlap_dofs, maps_.owned_dofs))) {
  ++instances_;
  if (model.mesh.dimension != 2)
    throw InputError(model.scene.file + ": flat shells need a 2D mid-surface mesh");
  // One kinematics for the model (scene/ShellChecks refuses a mix): finite rotations carry a
  // frame per overlap particle.
  finite_ = !model.parts.empty() &&
            model.parts.front().part->section.formulation == Formulation::total_lagrangian;
  if (finite_) frames_.assign(maps_.overlap_nodes->getNodeNumElements(), ShellFrame{});
  for (const auto& d : model.parts) {
    const auto& part = *d.part;
    const auto& material = *model.scene.find_material(part.material);
    if (material.model != "linear_elastic" && material.model != "j2_plasticity")
      throw InputError(model.scene.file + ": part '" + part.name +
                       "': shells take a linear_elastic or j2_plasticity material in this "
                       "version, not " +
                       material.model);
    if (d.points.scheme == Integration::gauss)
      throw InputError(model.scene.file + ": part '" + part.name +
                       "': shells are integrated at the particles (scni or nodal), not gauss");
    youngs_.push_back(material.constants.at("youngs_modulus"));
    poisson_.push_back(material.constants.at("poissons_ratio"));
    alpha_.push_back(part.shell ? part.shell->shear_stabilization : shear_stabilization);
    layers_.push_back(part.shell ? part.shell->thickness_points : thickness_points);
    if (material.model == "j2_plasticity") {
      j2_.push_back(material_law(model.scene, part, 2).j2);
      // small strain, every layer starts unstrained (eps_p = 0, alpha = 0)
      committed_.emplace_back(
          d.points.size() * static_cast<std::size_t>(layers_.back()) * physics::j2_state::count,
          0.0);
    } else {
      j2_.emplace_back();
      committed_.emplace_back();
    }
    trial_.push_back(committed_.back());
    // Direct gradients and values of the shape functions at the points (the shear rows).
    const auto& ip = d.points;
    const auto direct = evaluate_shape_functions(
        d.cloud, ip.x.data(), ip.size(), true,
        [&](std::size_t p) { return "shell point of particle " + std::to_string(ip.node[p] + 1); });
    const auto overlap_lid = [&](LocalIndex node) {
      return maps_.overlap_nodes->getLocalElement(global_node_id(model, node));
    };
    // each particle's thickness, by overlap index, interpolated at the points below
    const auto cloud_thickness = shell_particle_thickness(model, node_thickness_.size());
    node_thickness_.emplace_back(maps_.overlap_nodes->getNodeNumElements(), 0.0);
    const bool uniform = std::all_of(cloud_thickness.begin(), cloud_thickness.end(),
                                     [&](double t) { return t == cloud_thickness.front(); });
    uniform_thickness_.push_back(uniform && !cloud_thickness.empty() ? cloud_thickness.front()
                                                                     : 0.0);
    unit_section_.push_back(
        physics::elastic_mindlin_section(youngs_.back(), poisson_.back(), 1.0, layers_.back()));
    uniform_section_.push_back(physics::elastic_mindlin_section(
        youngs_.back(), poisson_.back(), uniform_thickness_.back(), layers_.back()));
    for (std::size_t i = 0; i < cloud_thickness.size(); ++i)
      node_thickness_.back()[static_cast<std::size_t>(overlap_lid(d.cloud.mesh_node[i]))] =
          cloud_thickness[i];
    std::vector<Point> points(ip.size());
    for (std::size_t q = 0; q < ip.size(); ++q) {
      std::map<LocalIndex, std::size_t> slot;  // cloud particle -> entry of the point
      Point& p = points[q];
      p.weight = ip.weight[q];
      p.spacing = shell_spacing(d.cloud, q);  // SCNI and nodal points: owned particles in order
      p.x = {ip.x[2 * q], ip.x[2 * q + 1]};
      p.owned_row = maps_.owned_nodes->getLocalElement(global_node_id(model, ip.node[q]));
      const auto entry = [&](LocalIndex particle) {
        const auto [it, added] = slot.emplace(particle, p.node.size());
        if (added) {
          p.node.push_back(overlap_lid(d.cloud.mesh_node[static_cast<std::size_t>(particle)]));
          p.b.insert(p.b.end(), {0.0, 0.0});
          p.g.insert(p.g.end(), {0.0, 0.0});
          p.phi.push_back(0.0);
        }
        return it->second;
      };
      for (auto k = ip.gradients.offsets[q]; k < ip.gradients.offsets[q + 1]; ++k) {
        const auto e = entry(ip.gradients.particles[k]);
        p.b[2 * e] = ip.gradients.values[2 * k];
        p.b[2 * e + 1] = ip.gradients.values[2 * k + 1];
      }
      for (auto k = direct.neighbors.offsets[q]; k < direct.neighbors.offsets[q + 1]; ++k) {
        const auto e = entry(direct.neighbors.particles[k]);
        p.phi[e] = direct.phi[k];
        p.g[2 * e] = direct.grad[2 * k];
        p.g[2 * e + 1] = direct.grad[2 * k + 1];
      }
      // the point is the particle (scni, nodal): its own thickness
      p.thickness = node_thickness_.back()[static_cast<std::size_t>(p.owned_row)];
    }
    points_.push_back(std::move(points));
  }
  if (finite_) reference_frames_ = frames_;
  build_reference();
}

void FlatShellOperator::build_reference() {
  for (std::size_t part = 0; part < model_.parts.size(); ++part)
    curved_ = curved_ || curved_part(model_, part);
  if (!curved_) return;
  if (!finite_)
    throw InputError(model_.scene.file +
                     ": a curved shell reference needs finite rotations (section.formulation: "
                     "total_lagrangian)");
  const auto& mesh = model_.mesh;
  const double step = shell_map_step(mesh);
  offset_.assign(frames_.size(), Vec3{});
  // a shell surface read in 3D: its nodes' positions and the mesh's frames (the same on every
  // rank; a ghost particle's MLS fit would miss the neighbours beyond the ghost layer)
  auto surface_frames =
      mesh.surface.empty() ? std::vector<ShellFrame>{} : surface_node_frames(mesh);
  if (!surface_frames.empty()) align_frames_to_supports(model_, surface_frames);
  for (const auto& d : model_.parts) {
    const auto& map = d.part->shell ? d.part->shell->reference : std::vector<ScalarField>{};
    if (map.empty() && surface_frames.empty()) continue;
    for (auto node : d.cloud.mesh_node) {
      const auto n = static_cast<std::size_t>(node);
      const auto lid = static_cast<std::size_t>(
          maps_.overlap_nodes->getLocalElement(global_node_id(model_, node)));
      const double* xy = mesh.coordinates.data() + 2 * n;
      if (!surface_frames.empty()) {
        const double* P = mesh.surface.data() + 3 * n;
        offset_[lid] = {P[0] - xy[0], P[1] - xy[1], P[2]};
        frames_[lid] = reference_frames_[lid] = surface_frames[n];
        continue;
      }
      const auto r = shell_reference_at(map, xy, step);
      offset_[lid] = {r.position[0] - xy[0], r.position[1] - xy[1], r.position[2]};
      frames_[lid] = reference_frames_[lid] = r.frame;
    }
  }
  // every point's strains at the reference state (d = 0), which its strains are measured from;
  // the metric of a non-isometric map turns them into the surface frame's, and the weights
  // (mesh areas) into surface areas (shells/ShellMetric.hpp)
  Vector zero(maps_.overlap_dofs);
  const auto d = zero.getLocalViewHost(Tpetra::Access::ReadOnly);
  FinitePoint fp;
  for (std::size_t part = 0; part < points_.size(); ++part)
    for (auto& p : points_[part]) {
      finite_point(p, d, fp);
      double e[shell_strains];
      finite_rotation_strains(fp.geometry, e);
      std::copy(e, e + shell_strains, p.reference.begin());
      const auto r = part_reference_at(model_, part, p.x.data());
      if (!r) continue;
      p.metric = r->metric;
      p.weight *= r->metric.area;
      p.spacing *= std::sqrt(r->metric.area);  // the particle spacing on the surface
    }
}

void FlatShellOperator::strain_rows(const Point& p, std::size_t a, const FinitePoint* fp,
                                    double (&B)[shell_strains][nd]) const {
  if (fp) {
    finite_rotation_rows(fp->geometry, fp->nodes[a], B);
    if (curved_) rows_to_surface(p.metric, B);
    return;
  }
  plate_strain_rows({p.b[2 * a], p.b[2 * a + 1]}, {p.g[2 * a], p.g[2 * a + 1]}, p.phi[a], B);
}

std::vector<double> FlatShellOperator::point_stiffness(const Point& p, const SectionTangent& S,
                                                       const FinitePoint* fp,
                                                       const double* R) const {
  const std::size_t n = p.node.size(), cols = n * nd;
  std::vector<double> K(cols * cols, 0.0);
  std::vector<std::array<std::array<double, nd>, shell_strains>> SB(n);
  std::vector<double> B(n * shell_strains * nd);
  for (std::size_t a = 0; a < n; ++a) {
    double Ba[shell_strains][nd], SBa[shell_strains][nd];
    strain_rows(p, a, fp, Ba);
    tangent_rows(S, Ba, SBa);
    for (int i = 0; i < shell_strains; ++i)
      for (int c = 0; c < nd; ++c) {
        B[(a * shell_strains + static_cast<std::size_t>(i)) * nd + static_cast<std::size_t>(c)] =
            Ba[i][c];
        SB[a][static_cast<std::size_t>(i)][static_cast<std::size_t>(c)] = SBa[i][c];
      }
  }
  for (std::size_t a = 0; a < n; ++a)
    for (std::size_t b = 0; b < n; ++b)
      for (std::size_t c = 0; c < nd; ++c)
        for (std::size_t e = 0; e < nd; ++e) {
          double v = 0;
          for (std::size_t i = 0; i < shell_strains; ++i)
            v += B[(a * shell_strains + i) * nd + c] * SB[b][i][e];
          K[(a * nd + c) * cols + b * nd + e] = p.weight * v;
        }
  if (!fp) return K;
  // the geometric block of the mesh-coordinate strains takes their conjugate resultants
  double resultants[shell_strains], G[nd][nd];
  std::copy(R, R + shell_strains, resultants);
  if (curved_) resultants_to_mesh(p.metric, R, 1.0, resultants);
  for (std::size_t a = 0; a < n; ++a)
    for (std::size_t b = 0; b < n; ++b) {
      finite_rotation_geometric(fp->geometry, resultants, fp->nodes[a], fp->nodes[b], a == b, G);
      for (std::size_t c = 0; c < nd; ++c)
        for (std::size_t e = 0; e < nd; ++e)
          K[(a * nd + c) * cols + b * nd + e] += p.weight * G[c][e];
    }
  return K;
}

Teuchos::RCP<FlatShellOperator::Matrix> FlatShellOperator::create_matrix(
    const ShellConstraints& constraints) const {
  CouplingGraph couplings(maps_.overlap_nodes->getNodeNumElements());
  for (const auto& part : points_)
    for (const auto& p : part) couplings.add_clique(p.node.data(), p.node.size());
  constraints.add_couplings(couplings);
  return Teuchos::rcp(new Matrix(couplings.build(maps_)));
}

Teuchos::RCP<FlatShellOperator::Matrix> FlatShellOperator::stiffness(
    const ShellConstraints& constraints) const {
  auto K = create_matrix(constraints);
  fill_tangent(Vector(maps_.owned_dofs), constraints, *K);
  return K;
}

void FlatShellOperator::fill_tangent(const Vector& d_owned, const ShellConstraints& constraints,
                                     Matrix& K, const Pressure* follower) const {
  const auto d_overlap = to_overlap(d_owned);
  K.beginAssembly();
  K.setAllToScalar(0.0);
  std::vector<int> cols;
  FinitePoint fp;
  {
    const auto d = d_overlap.getLocalViewHost(Tpetra::Access::ReadOnly);
    for (std::size_t part = 0; part < points_.size(); ++part) {
      const std::size_t block = history_size(part);
      for (std::size_t q = 0; q < points_[part].size(); ++q) {
        const auto& p = points_[part][q];
        double e[shell_strains], R[shell_strains];
        SectionTangent S;
        if (finite_) {
          finite_point(p, d, fp);
          finite_strains(p, fp, e);
        } else {
          point_strains(p, d, e);
        }
        shell_section_response(section_law(part, p.spacing, p.thickness), e,
                               block ? committed_[part].data() + q * block : nullptr,
                               block ? trial_[part].data() + q * block : nullptr, R, &S);
        const auto Kp = finite_ ? point_stiffness(p, S, &fp, R) : point_stiffness(p, S);
        const std::size_t n = p.node.size(), width = n * nd;
        cols.resize(width);
        for (std::size_t a = 0; a < n; ++a)
          for (std::size_t c = 0; c < nd; ++c)
            cols[a * nd + c] = p.node[a] * nd + static_cast<int>(c);
        for (std::size_t r = 0; r < width; ++r)
          K.sumIntoLocalValues(cols[r], static_cast<int>(width), Kp.data() + r * width,
                               cols.data());
        if (follower) add_follower_stiffness(part, p, d, *follower, cols, K);
      }
    }
  }
  constraints.add_edge_terms(d_overlap, K);
  K.endAssembly();
  K.beginModify();
  constraints.replace_rows(K);
  K.endModify();
}

template <class View>
void FlatShellOperator::surface_tangents(const Point& p, const View& d, Vec3 (&f)[2]) const {
  f[0] = {1, 0, 0};
  f[1] = {0, 1, 0};
  for (std::size_t a = 0; a < p.node.size(); ++a)
    for (std::size_t c = 0; c < 3; ++c) {
      const double u = d(static_cast<std::size_t>(p.node[a]) * nd + c, 0) +
                       (curved_ ? offset_[static_cast<std::size_t>(p.node[a])][c] : 0.0);
      f[0][c] += p.g[2 * a] * u;
      f[1][c] += p.g[2 * a + 1] * u;
    }
}

template <class View>
void FlatShellOperator::add_follower_stiffness(std::size_t part, const Point& p, const View& d,
                                               const Pressure& q, const std::vector<int>& cols,
                                               Matrix& K) const {
  Vec3 f[2];
  surface_tangents(p, d, f);
  const double x[3] = {p.x[0], p.x[1], 0.0};
  const double load = p.weight / p.metric.area * q(part, x);  // f1 x f2: per unit mesh area
  if (load == 0) return;
  const std::size_t n = p.node.size(), width = n * nd;
  std::vector<double> row(width);
  // d(f1 x f2)/du_(J,l) = g_J1 e_l x f2 + f1 x g_J2 e_l; the residual has -f_ext
  for (std::size_t a = 0; a < n; ++a)
    for (std::size_t i = 0; i < 3; ++i) {
      std::fill(row.begin(), row.end(), 0.0);
      for (std::size_t b = 0; b < n; ++b)
        for (std::size_t l = 0; l < 3; ++l) {
          Vec3 e{};
          e[l] = 1;
          const Vec3 x1 = cross(e, f[1]), x2 = cross(f[0], e);  // e_l x f2, f1 x e_l
          row[b * nd + l] = -load * p.phi[a] * (p.g[2 * b] * x1[i] + p.g[2 * b + 1] * x2[i]);
        }
      K.sumIntoLocalValues(cols[a * nd + i], static_cast<int>(width), row.data(), cols.data());
    }
}

void FlatShellOperator::add_follower_pressure(const Pressure& q, const Vector& d_owned,
                                              Vector& f_owned) const {
  const auto d_overlap = to_overlap(d_owned);
  Vector f_overlap(maps_.overlap_dofs);
  {
    const auto d = d_overlap.getLocalViewHost(Tpetra::Access::ReadOnly);
    auto f = f_overlap.getLocalViewHost(Tpetra::Access::ReadWrite);
    for (std::size_t part = 0; part < points_.size(); ++part)
      for (const auto& p : points_[part]) {
        Vec3 t[2];
        surface_tangents(p, d, t);
        const double x[3] = {p.x[0], p.x[1], 0.0};
        const double load = p.weight / p.metric.area * q(part, x);  // per unit mesh area
        const Vec3 area = cross(t[0], t[1]);
        for (std::size_t a = 0; a < p.node.size(); ++a)
          for (std::size_t c = 0; c < 3; ++c)
            f(static_cast<std::size_t>(p.node[a]) * nd + c, 0) += load * p.phi[a] * area[c];
      }
  }
  add_overlap(f_overlap, f_owned);
}

void FlatShellOperator::add_pressure(const Pressure& q, Vector& f_owned) const {
  Vector f_overlap(maps_.overlap_dofs);
  {
    auto f = f_overlap.getLocalViewHost(Tpetra::Access::ReadWrite);
    for (std::size_t part = 0; part < points_.size(); ++part)
      for (const auto& p : points_[part]) {
        const double x[3] = {p.x[0], p.x[1], 0.0};
        const double load = p.weight * q(part, x);
        for (std::size_t a = 0; a < p.node.size(); ++a)
          f(static_cast<std::size_t>(p.node[a]) * nd + shell_w, 0) += load * p.phi[a];
      }
  }
  f_owned.doExport(f_overlap, *exporter_, Tpetra::ADD);
}

FlatShellOperator::Vector FlatShellOperator::to_overlap(const Vector& d_owned) const {
  Vector d(maps_.overlap_dofs);
  to_overlap(d_owned, d);
  return d;
}

void FlatShellOperator::export_add(const Vector& f_overlap, Vector& f_owned) const {
  f_owned.putScalar(0.0);
  f_owned.doExport(f_overlap, *exporter_, Tpetra::ADD);
}

void FlatShellOperator::accept_rotations(Vector& d_owned) const {
  const auto d_overlap = to_overlap(d_owned);
  {
    const auto d = d_overlap.getLocalViewHost(Tpetra::Access::ReadOnly);
    for (std::size_t i = 0; i < frames_.size(); ++i)
      rotate_frame(frames_[i], d(i * nd + shell_rx, 0), d(i * nd + shell_ry, 0));
  }
  auto d = d_owned.getLocalViewHost(Tpetra::Access::ReadWrite);
  for (std::size_t i = 0; i < d.extent(0); i += nd) d(i + shell_rx, 0) = d(i + shell_ry, 0) = 0;
}

std::vector<double> FlatShellOperator::physical_values(const Vector& d_owned) const {
  const auto d_overlap = to_overlap(d_owned);
  const auto d = d_overlap.getLocalViewHost(Tpetra::Access::ReadOnly);
  const auto& owned = *maps_.owned_nodes;
  const auto& overlap = *maps_.overlap_nodes;
  std::vector<double> out(owned.getNodeNumElements() * nd, 0.0);
  for (const auto& part : model_.parts) {
    const auto& rows = part.particle_values();
    for (std::size_t r = 0; r < part.cloud.owned_count; ++r) {
      const auto row = static_cast<std::size_t>(
          owned.getLocalElement(global_node_id(model_, part.cloud.mesh_node[r])));
      std::vector<int> lids;  // finite rotations: the rotation from the reference director
      for (auto k = rows.offsets[r]; k < rows.offsets[r + 1]; ++k) {
        const auto node = part.cloud.mesh_node[static_cast<std::size_t>(rows.particles[k])];
        const auto lid =
            static_cast<std::size_t>(overlap.getLocalElement(global_node_id(model_, node)));
        for (std::size_t c = 0; c < nd; ++c)
          out[row * nd + c] += rows.values[k] * d(lid * nd + c, 0);
        lids.push_back(static_cast<int>(lid));
      }
      if (finite_)
        physical_rotation(lids.data(), rows.values.data() + rows.offsets[r], lids.size(), d,
                          out[row * nd + shell_rx], out[row * nd + shell_ry]);
    }
  }
  return out;
}

}  // namespace efg
