#include "shells/FlatShellOperator.hpp"

#include <Teuchos_CommHelpers.hpp>
#include <Tpetra_Import.hpp>

#include <algorithm>
#include <map>
#include <stdexcept>
#include <utility>

#include "core/Errors.hpp"
#include "discretization/ShapeFunctions.hpp"
#include "materials/ShellSectionJ2.hpp"
#include "model/MaterialLaws.hpp"
#include "operators/CouplingGraph.hpp"
#include "shells/ShellConstraints.hpp"
#include "shells/ShellMass.hpp"
#include "shells/ShellSpacing.hpp"

namespace efg {
namespace {

constexpr int nd = shell_dofs_per_node;

}  // namespace

FlatShellOperator::FlatShellOperator(const Model& model, int thickness_points,
                                     double shear_stabilization)
    : model_(model), maps_(make_dof_maps(model.maps.owned_nodes->getComm(), model.partition, nd)) {
  ++instances_;
  if (model.mesh.dimension != 2)
    throw InputError(model.scene.file + ": flat shells need a 2D mid-surface mesh");
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
    const double t = part.shell ? part.shell->thickness : part.thickness;
    sections_.push_back(physics::elastic_mindlin_section(
        material.constants.at("youngs_modulus"), material.constants.at("poissons_ratio"), t,
        part.shell ? part.shell->thickness_points : thickness_points));
    thickness_.push_back(t);
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
      return maps_.overlap_nodes->getLocalElement(static_cast<GlobalOrdinal>(node));
    };
    std::vector<Point> points(ip.size());
    for (std::size_t q = 0; q < ip.size(); ++q) {
      std::map<LocalIndex, std::size_t> slot;  // cloud particle -> entry of the point
      Point& p = points[q];
      p.weight = ip.weight[q];
      p.spacing = shell_spacing(d.cloud, q);  // SCNI and nodal points: owned particles in order
      p.x = {ip.x[2 * q], ip.x[2 * q + 1]};
      p.owned_row = maps_.owned_nodes->getLocalElement(static_cast<GlobalOrdinal>(ip.node[q]));
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
    }
    points_.push_back(std::move(points));
  }
}

std::vector<double> FlatShellOperator::point_stiffness(const Point& p, std::size_t part) const {
  const auto s = section_at(part, p.spacing);
  const std::size_t n = p.node.size(), cols = n * nd;
  std::vector<double> K(cols * cols, 0.0);
  std::vector<std::array<std::array<double, nd>, shell_strains>> SB(n);
  std::vector<double> B(n * shell_strains * nd);
  for (std::size_t a = 0; a < n; ++a) {
    double Ba[shell_strains][nd], SBa[shell_strains][nd];
    plate_strain_rows({p.b[2 * a], p.b[2 * a + 1]}, {p.g[2 * a], p.g[2 * a + 1]}, p.phi[a], Ba);
    resultant_rows(s, Ba, SBa);
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
  return K;
}

Teuchos::RCP<FlatShellOperator::Matrix> FlatShellOperator::stiffness(
    const ShellConstraints& constraints) const {
  CouplingGraph couplings(maps_.overlap_nodes->getNodeNumElements());
  for (const auto& part : points_)
    for (const auto& p : part) couplings.add_clique(p.node.data(), p.node.size());
  constraints.add_couplings(couplings);
  auto K = Teuchos::rcp(new Matrix(couplings.build(maps_)));
  K->beginAssembly();
  std::vector<int> cols;
  for (std::size_t part = 0; part < points_.size(); ++part)
    for (const auto& p : points_[part]) {
      const auto Kp = point_stiffness(p, part);
      const std::size_t n = p.node.size(), width = n * nd;
      cols.resize(width);
      for (std::size_t a = 0; a < n; ++a)
        for (std::size_t c = 0; c < nd; ++c)
          cols[a * nd + c] = p.node[a] * nd + static_cast<int>(c);
      for (std::size_t r = 0; r < width; ++r)
        K->sumIntoLocalValues(cols[r], static_cast<int>(width), Kp.data() + r * width, cols.data());
    }
  constraints.add_edge_terms(*K);
  K->endAssembly();
  K->beginModify();
  constraints.replace_rows(*K);
  K->endModify();
  return K;
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
  Tpetra::Export<> exporter(maps_.overlap_dofs, maps_.owned_dofs);
  f_owned.doExport(f_overlap, exporter, Tpetra::ADD);
}

FlatShellOperator::Vector FlatShellOperator::to_overlap(const Vector& d_owned) const {
  Vector d(maps_.overlap_dofs);
  Tpetra::Import<> importer(maps_.owned_dofs, maps_.overlap_dofs);
  d.doImport(d_owned, importer, Tpetra::INSERT);
  return d;
}

std::vector<double> FlatShellOperator::physical_values(const Vector& d_owned) const {
  const auto d_overlap = to_overlap(d_owned);
  const auto d = d_overlap.getLocalViewHost(Tpetra::Access::ReadOnly);
  const auto& owned = *maps_.owned_nodes;
  const auto& overlap = *maps_.overlap_nodes;
  std::vector<double> out(owned.getNodeNumElements() * nd, 0.0);
  for (const auto& part : model_.parts) {
    const auto& rows = part.particle_values;
    for (std::size_t r = 0; r < part.cloud.owned_count; ++r) {
      const auto row = static_cast<std::size_t>(
          owned.getLocalElement(static_cast<GlobalOrdinal>(part.cloud.mesh_node[r])));
      for (auto k = rows.offsets[r]; k < rows.offsets[r + 1]; ++k) {
        const auto node = part.cloud.mesh_node[static_cast<std::size_t>(rows.particles[k])];
        const auto lid = static_cast<std::size_t>(overlap.getLocalElement(node));
        for (std::size_t c = 0; c < nd; ++c)
          out[row * nd + c] += rows.values[k] * d(lid * nd + c, 0);
      }
    }
  }
  return out;
}

template <class View>
void FlatShellOperator::point_strains(const Point& p, const View& d,
                                      double (&e)[shell_strains]) const {
  for (auto& v : e) v = 0;
  for (std::size_t a = 0; a < p.node.size(); ++a) {
    double B[shell_strains][nd];
    plate_strain_rows({p.b[2 * a], p.b[2 * a + 1]}, {p.g[2 * a], p.g[2 * a + 1]}, p.phi[a], B);
    for (std::size_t c = 0; c < nd; ++c) {
      const double dc = d(static_cast<std::size_t>(p.node[a]) * nd + c, 0);
      for (std::size_t i = 0; i < shell_strains; ++i) e[i] += B[i][c] * dc;
    }
  }
}

template <class View>
void FlatShellOperator::plastic_resultants(std::size_t part, std::size_t q, const Point& p,
                                           const View& d, double (&e)[shell_strains],
                                           double (&R)[shell_strains]) const {
  point_strains(p, d, e);
  const auto law = elastic_probe_ ? physics::without_yield(*j2_[part]) : *j2_[part];
  const std::size_t block = static_cast<std::size_t>(layers_[part]) * physics::j2_state::count;
  double N[3], M[3];
  physics::j2_section_resultants(law, thickness_[part], layers_[part], {e[0], e[1], e[2]},
                                 {e[3], e[4], e[5]}, committed_[part].data() + q * block,
                                 trial_[part].data() + q * block, 0.0, N, M);
  const double shear = section_at(part, p.spacing).shear;
  for (int i = 0; i < 3; ++i) {
    R[i] = N[i];
    R[3 + i] = M[i];
  }
  R[6] = shear * e[6];
  R[7] = shear * e[7];
}

template <class View>
void FlatShellOperator::point_resultants(std::size_t part, const Point& p, const View& d,
                                         double (&e)[shell_strains],
                                         double (&R)[shell_strains]) const {
  if (j2_[part]) {
    const auto q = static_cast<std::size_t>(&p - points_[part].data());
    return plastic_resultants(part, q, p, d, e, R);
  }
  point_strains(p, d, e);
  double N[3], M[3], Q[2];
  physics::mindlin_resultants(section_at(part, p.spacing), {e[0], e[1], e[2]}, {e[3], e[4], e[5]},
                              {e[6], e[7]}, N, M, Q);
  for (int i = 0; i < 3; ++i) {
    R[i] = N[i];
    R[3 + i] = M[i];
  }
  R[6] = Q[0];
  R[7] = Q[1];
}

std::vector<double> FlatShellOperator::resultants(const Vector& d_owned) const {
  const auto d_overlap = to_overlap(d_owned);
  const auto d = d_overlap.getLocalViewHost(Tpetra::Access::ReadOnly);
  std::vector<double> out(maps_.owned_nodes->getNodeNumElements() * shell_strains, 0.0);
  for (std::size_t part = 0; part < points_.size(); ++part)
    for (const auto& p : points_[part]) {
      double e[shell_strains], R[shell_strains];
      point_resultants(part, p, d, e, R);
      std::copy(R, R + shell_strains,
                out.begin() + static_cast<std::ptrdiff_t>(p.owned_row) * shell_strains);
    }
  return out;
}

double FlatShellOperator::strain_energy(const Vector& d_owned) const {
  // 1/2 a_L e . S e per point, the same as 1/2 d^T K_L d without forming K_L.
  const auto d_overlap = to_overlap(d_owned);
  const auto d = d_overlap.getLocalViewHost(Tpetra::Access::ReadOnly);
  double energy = 0;
  for (std::size_t part = 0; part < points_.size(); ++part)
    for (const auto& p : points_[part]) {
      double e[shell_strains], R[shell_strains], work = 0;
      point_resultants(part, p, d, e, R);
      if (!j2_[part]) {
        for (int i = 0; i < shell_strains; ++i) work += R[i] * e[i];
        energy += 0.5 * p.weight * work;
        continue;
      }
      // stored + dissipated energy of the committed layers (per unit volume, times dz), and
      // the elastic transverse shear
      double xi[physics::max_thickness_points], w[physics::max_thickness_points];
      const int n = physics::thickness_rule(layers_[part], xi, w);
      const auto q = static_cast<std::size_t>(&p - points_[part].data());
      const double* state =
          committed_[part].data() + q * static_cast<std::size_t>(n) * physics::j2_state::count;
      for (int k = 0; k < n; ++k)
        work += 0.5 * thickness_[part] * w[k] *
                (state[k * physics::j2_state::count + physics::j2_state::elastic_energy] +
                 state[k * physics::j2_state::count + physics::j2_state::dissipation]);
      energy += p.weight * (work + 0.5 * (R[6] * e[6] + R[7] * e[7]));
    }
  return energy;
}

void FlatShellOperator::internal_force(const Vector& d_owned, Vector& f_owned) const {
  const auto d_overlap = to_overlap(d_owned);
  Vector f_overlap(maps_.overlap_dofs);
  {
    const auto d = d_overlap.getLocalViewHost(Tpetra::Access::ReadOnly);
    auto f = f_overlap.getLocalViewHost(Tpetra::Access::ReadWrite);
    for (std::size_t part = 0; part < points_.size(); ++part)
      for (const auto& p : points_[part]) {
        double e[shell_strains], R[shell_strains];
        point_resultants(part, p, d, e, R);
        for (std::size_t a = 0; a < p.node.size(); ++a) {
          double B[shell_strains][nd];
          plate_strain_rows({p.b[2 * a], p.b[2 * a + 1]}, {p.g[2 * a], p.g[2 * a + 1]}, p.phi[a],
                            B);
          for (std::size_t c = 0; c < nd; ++c) {
            double v = 0;
            for (std::size_t i = 0; i < shell_strains; ++i) v += B[i][c] * R[i];
            f(static_cast<std::size_t>(p.node[a]) * nd + c, 0) += p.weight * v;
          }
        }
      }
  }
  f_owned.putScalar(0.0);
  Tpetra::Export<> exporter(maps_.overlap_dofs, maps_.owned_dofs);
  f_owned.doExport(f_overlap, exporter, Tpetra::ADD);
}

FlatShellOperator::Vector FlatShellOperator::lumped_mass() const {
  // Row sums m_I = sum_L rho t a_L phi_I(X_L) (the shape functions sum to one, so the total mass
  // is exact), gathered on the overlap nodes and summed into their owners; the spacing h_I of
  // the particle's own point (SCNI and nodal points are the owned particles) scales the rotary
  // inertia.
  Vector m_overlap(maps_.overlap_dofs);
  std::vector<double> spacing(maps_.owned_nodes->getNodeNumElements(), 0.0),
      thickness(spacing.size(), 0.0);
  {
    auto m = m_overlap.getLocalViewHost(Tpetra::Access::ReadWrite);
    for (std::size_t part = 0; part < points_.size(); ++part) {
      const auto& d = model_.parts[part];
      const auto& material = *model_.scene.find_material(d.part->material);
      if (!material.density)
        throw InputError(model_.scene.file + ": material '" + material.name +
                         "' needs a density for an explicit stage (part '" + d.part->name + "')");
      const double areal = *material.density * thickness_[part];
      for (const auto& p : points_[part]) {
        spacing[static_cast<std::size_t>(p.owned_row)] = p.spacing;
        thickness[static_cast<std::size_t>(p.owned_row)] = thickness_[part];
        for (std::size_t a = 0; a < p.node.size(); ++a)
          m(static_cast<std::size_t>(p.node[a]) * nd, 0) += areal * p.weight * p.phi[a];
      }
    }
  }
  Vector m_owned(maps_.owned_dofs);
  Tpetra::Export<> exporter(maps_.overlap_dofs, maps_.owned_dofs);
  m_owned.doExport(m_overlap, exporter, Tpetra::ADD);
  auto m = m_owned.getLocalViewHost(Tpetra::Access::ReadWrite);
  for (std::size_t i = 0; i < spacing.size(); ++i) {
    const double mass = m(i * nd, 0);
    if (!(mass > 0))
      throw NumericalError(
          "shell lumped mass: particle " +
          std::to_string(maps_.owned_nodes->getGlobalElement(static_cast<int>(i)) + 1) +
          " has mass " + std::to_string(mass) + " (<= 0)");
    const double rotary = mass * shell_rotary_inertia_factor(thickness[i], spacing[i]);
    for (std::size_t c = 0; c < nd; ++c) m(i * nd + c, 0) = c < shell_rx ? mass : rotary;
  }
  return m_owned;
}

bool FlatShellOperator::plastic() const {
  for (const auto& law : j2_)
    if (law) return true;
  return false;
}

void FlatShellOperator::commit_state() const {
  // Every evaluation writes the trial state of every point of a J2 part, so the old committed
  // states may become the next trial buffer: a swap, not a copy.
  std::swap(committed_, trial_);
}

std::vector<double> FlatShellOperator::plastic_strain() const {
  std::vector<double> out(maps_.owned_nodes->getNodeNumElements(), 0.0);
  for (std::size_t part = 0; part < points_.size(); ++part) {
    if (!j2_[part]) continue;
    const auto n = static_cast<std::size_t>(layers_[part]);
    for (std::size_t q = 0; q < points_[part].size(); ++q) {
      double& largest = out[static_cast<std::size_t>(points_[part][q].owned_row)];
      for (std::size_t k = 0; k < n; ++k)
        largest = std::max(
            largest,
            committed_[part][(q * n + k) * physics::j2_state::count + physics::j2_state::alpha]);
    }
  }
  return out;
}

std::vector<double> FlatShellOperator::surface_stresses(const Vector& d_owned) const {
  const auto d_overlap = to_overlap(d_owned);
  const auto d = d_overlap.getLocalViewHost(Tpetra::Access::ReadOnly);
  std::vector<double> out(maps_.owned_nodes->getNodeNumElements() * 6, 0.0);
  for (std::size_t part = 0; part < points_.size(); ++part) {
    const double t = thickness_[part];
    for (std::size_t q = 0; q < points_[part].size(); ++q) {
      const auto& p = points_[part][q];
      double* o = &out[static_cast<std::size_t>(p.owned_row) * 6];
      double e[shell_strains];
      point_strains(p, d, e);
      if (!j2_[part]) {
        double R[shell_strains];
        point_resultants(part, p, d, e, R);
        for (std::size_t c = 0; c < 3; ++c) {
          o[c] = R[c] / t + 6 * R[3 + c] / (t * t);
          o[3 + c] = R[c] / t - 6 * R[3 + c] / (t * t);
        }
        continue;
      }
      const int n = layers_[part];
      const double* states =
          committed_[part].data() + q * static_cast<std::size_t>(n) * physics::j2_state::count;
      double top[3], bottom[3];
      physics::j2_layer_stress(*j2_[part], t, n, n - 1, {e[0], e[1], e[2]}, {e[3], e[4], e[5]},
                               states, top);
      physics::j2_layer_stress(*j2_[part], t, n, 0, {e[0], e[1], e[2]}, {e[3], e[4], e[5]}, states,
                               bottom);
      for (std::size_t c = 0; c < 3; ++c) {
        o[c] = top[c];
        o[3 + c] = bottom[c];
      }
    }
  }
  return out;
}

}  // namespace efg
