// FlatShellOperator's response to a displacement (src/shells/FlatShellOperator.hpp): resultants,
// energies, the internal force of explicit stages, the lumped mass, the J2 layers' commit and
// output; the setup and the assembled stiffness are in FlatShellOperator.cpp.
#include <Teuchos_CommHelpers.hpp>
#include <Tpetra_Import.hpp>

#include <algorithm>
#include <string>
#include <utility>

#include "core/Errors.hpp"
#include "shells/FlatShellPointLaw.hpp"
#include "shells/ShellConstraints.hpp"
#include "shells/ShellMass.hpp"

namespace efg {
namespace {

constexpr int nd = shell_dofs_per_node;

}  // namespace

void FlatShellOperator::strain_resultants(std::size_t part, const Point& p,
                                          const double (&e)[shell_strains],
                                          double (&R)[shell_strains]) const {
  // the section law of shells/ShellSectionResponse.hpp; while the elastic probe is on, J2
  // layers answer elastically from their committed states
  auto law = section_law(part, p.spacing, p.thickness);
  physics::J2Parameters elastic;
  if (law.j2 && elastic_probe_) {
    elastic = physics::without_yield(*law.j2);
    law.j2 = &elastic;
  }
  const std::size_t block = history_size(part);
  const auto q = static_cast<std::size_t>(&p - points_[part].data());
  shell_section_response(law, e, block ? committed_[part].data() + q * block : nullptr,
                         block ? trial_[part].data() + q * block : nullptr, R);
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
      if (!j2_[part]) {
        point_resultants(part, p, d, e, R);
        for (int i = 0; i < shell_strains; ++i) work += R[i] * e[i];
        energy += 0.5 * p.weight * work;
        continue;
      }
      // stored + dissipated energy of the committed layers (per unit volume, times dz: no
      // return map needed), and the elastic transverse shear
      point_strains(p, d, e);
      const double shear = section_at(part, p.spacing, p.thickness).shear;
      double xi[physics::max_thickness_points], w[physics::max_thickness_points];
      const int n = physics::thickness_rule(layers_[part], xi, w);
      const auto q = static_cast<std::size_t>(&p - points_[part].data());
      const double* state =
          committed_[part].data() + q * static_cast<std::size_t>(n) * physics::j2_state::count;
      for (int k = 0; k < n; ++k)
        work += 0.5 * p.thickness * w[k] *
                (state[k * physics::j2_state::count + physics::j2_state::elastic_energy] +
                 state[k * physics::j2_state::count + physics::j2_state::dissipation]);
      energy += p.weight * (work + 0.5 * shear * (e[6] * e[6] + e[7] * e[7]));
    }
  return energy;
}

void FlatShellOperator::internal_force(const Vector& d_owned, Vector& f_owned,
                                       const ShellConstraints* edges) const {
  const auto d_overlap = to_overlap(d_owned);
  Vector f_overlap(maps_.overlap_dofs);
  {
    const auto d = d_overlap.getLocalViewHost(Tpetra::Access::ReadOnly);
    auto f = f_overlap.getLocalViewHost(Tpetra::Access::ReadWrite);
    FinitePoint fp;
    for (std::size_t part = 0; part < points_.size(); ++part)
      for (const auto& p : points_[part]) {
        double e[shell_strains], R[shell_strains];
        if (finite_) {  // the point's kinematics once: for its strains and its rows
          finite_point(p, d, fp);
          finite_strains(p, fp, e);
          strain_resultants(part, p, e, R);
        } else {
          point_resultants(part, p, d, e, R);
        }
        for (std::size_t a = 0; a < p.node.size(); ++a) {
          double B[shell_strains][nd];
          strain_rows(p, a, finite_ ? &fp : nullptr, B);
          for (std::size_t c = 0; c < nd; ++c) {
            double v = 0;
            for (std::size_t i = 0; i < shell_strains; ++i) v += B[i][c] * R[i];
            f(static_cast<std::size_t>(p.node[a]) * nd + c, 0) += p.weight * v;
          }
        }
      }
  }
  if (edges) edges->add_edge_forces(d_overlap, f_overlap);
  export_add(f_overlap, f_owned);
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
      for (const auto& p : points_[part]) {
        const double areal = *material.density * p.thickness;
        spacing[static_cast<std::size_t>(p.owned_row)] = p.spacing;
        thickness[static_cast<std::size_t>(p.owned_row)] = p.thickness;
        for (std::size_t a = 0; a < p.node.size(); ++a)
          m(static_cast<std::size_t>(p.node[a]) * nd, 0) += areal * p.weight * p.phi[a];
      }
    }
  }
  Vector m_owned(maps_.owned_dofs);
  export_add(m_overlap, m_owned);
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

std::vector<double> FlatShellOperator::thickness(const Vector& d_owned) const {
  const auto d_overlap = to_overlap(d_owned);
  const auto d = d_overlap.getLocalViewHost(Tpetra::Access::ReadOnly);
  std::vector<double> out(maps_.owned_nodes->getNodeNumElements(), 0.0);
  for (std::size_t part = 0; part < points_.size(); ++part) {
    const auto& material = *model_.scene.find_material(model_.parts[part].part->material);
    const double nu = material.constants.at("poissons_ratio");
    const int n = layers_[part];
    double xi[physics::max_thickness_points], w[physics::max_thickness_points];
    physics::thickness_rule(n, xi, w);
    for (std::size_t q = 0; q < points_[part].size(); ++q) {
      const auto& p = points_[part][q];
      double mean = 0;  // eps_zz through the thickness
      if (j2_[part]) {
        const double* state =
            committed_[part].data() + q * static_cast<std::size_t>(n) * physics::j2_state::count;
        for (int k = 0; k < n; ++k)  // Gauss weights on [-1, 1] sum to 2
          mean +=
              0.5 * w[k] * state[k * physics::j2_state::count + physics::j2_state::out_of_plane];
      } else {
        double e[shell_strains];
        point_strains(p, d, e);
        mean = -nu / (1 - nu) * (e[0] + e[1]);
      }
      out[static_cast<std::size_t>(p.owned_row)] = p.thickness * (1 + mean);
    }
  }
  return out;
}

std::vector<double> FlatShellOperator::surface_stresses(const Vector& d_owned) const {
  const auto d_overlap = to_overlap(d_owned);
  const auto d = d_overlap.getLocalViewHost(Tpetra::Access::ReadOnly);
  std::vector<double> out(maps_.owned_nodes->getNodeNumElements() * 9, 0.0);
  for (std::size_t part = 0; part < points_.size(); ++part) {
    for (std::size_t q = 0; q < points_[part].size(); ++q) {
      const auto& p = points_[part][q];
      const double t = p.thickness;
      double* o = &out[static_cast<std::size_t>(p.owned_row) * 9];
      double e[shell_strains];
      if (!j2_[part]) {
        double R[shell_strains];
        point_resultants(part, p, d, e, R);
        for (std::size_t c = 0; c < 3; ++c) {
          o[c] = R[c] / t + 6 * R[3 + c] / (t * t);
          o[3 + c] = R[c] / t;
          o[6 + c] = R[c] / t - 6 * R[3 + c] / (t * t);
        }
        continue;
      }
      point_strains(p, d, e);
      const int n = layers_[part];
      const double* states =
          committed_[part].data() + q * static_cast<std::size_t>(n) * physics::j2_state::count;
      const auto layer = [&](int k, double(&s)[3]) {
        physics::j2_layer_stress(*j2_[part], t, n, k, {e[0], e[1], e[2]}, {e[3], e[4], e[5]},
                                 states, s);
      };
      // the mid-surface: the middle layer of an odd rule, the mean of the two middle ones of an
      // even rule (symmetric about z = 0)
      double top[3], bottom[3], below[3], above[3];
      layer(n - 1, top);
      layer(0, bottom);
      layer((n - 1) / 2, below);
      layer(n / 2, above);
      for (std::size_t c = 0; c < 3; ++c) {
        o[c] = top[c];
        o[3 + c] = 0.5 * (below[c] + above[c]);
        o[6 + c] = bottom[c];
      }
    }
  }
  return out;
}

}  // namespace efg
