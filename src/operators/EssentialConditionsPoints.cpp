// The boundary points' terms of the essential conditions (EssentialConditions.hpp): the state
// at a point (interpolated displacement and gradient, the stress of the point's law, a mixed
// part's cell pressure), and from it the residual and tangent terms of the transformation,
// Nitsche and penalty methods, and the history update of plastic points.
#include <algorithm>
#include <cmath>

#include "core/Errors.hpp"
#include "model/GradedMaterials.hpp"
#include "operators/BoundaryCellPressure.hpp"
#include "operators/EssentialConditions.hpp"

namespace efg {

template <int Dim>
void EssentialConditions::interpolate_at(const BoundaryPoint& p, const Vector& d_overlap,
                                         double (&u)[Dim], double (&H)[Dim][Dim]) {
  const auto d = d_overlap.getLocalViewHost(Tpetra::Access::ReadOnly);
  for (std::size_t a = 0; a < p.nodes.size(); ++a)
    for (int i = 0; i < Dim; ++i) {
      const double di = d(static_cast<std::size_t>(p.nodes[a] * Dim + i), 0);
      u[i] += p.phi[a] * di;
      for (int j = 0; j < Dim; ++j) H[i][j] += di * p.grad[a * Dim + static_cast<std::size_t>(j)];
    }
}

template <int Dim>
void EssentialConditions::update_point_history(const BoundaryPoint& p,
                                               const Vector& d_overlap) const {
  double H[Dim][Dim] = {}, u[Dim] = {};
  interpolate_at<Dim>(p, d_overlap, u, H);
  double P[Dim][Dim] = {};
  if (!boundary_stress<Dim>(p, H, P, nullptr))
    throw NumericalError("det F <= 0 at a boundary point of an essential condition");
}

void EssentialConditions::update_history(const Vector& d_overlap) const {
  for (const auto& p : points_) {
    if (!p.law.plastic) continue;
    if (dim_ == 2)
      update_point_history<2>(p, d_overlap);
    else
      update_point_history<3>(p, d_overlap);
  }
}

template <int Dim>
bool EssentialConditions::boundary_stress(const BoundaryPoint& p, const double (&H)[Dim][Dim],
                                          double (&P)[Dim][Dim],
                                          double (*A)[Dim][Dim][Dim][Dim]) const {
  if (!p.law.plastic) return physics::stress<Dim>(p.law.elastic, H, P, A ? *A : nullptr);
  using State = double[physics::j2_state::count];
  const auto& old_state = *reinterpret_cast<const State*>(&committed_[p.history]);
  auto& new_state = *reinterpret_cast<State*>(&trial_[p.history]);
  double cauchy[3][3];
  if (p.law.low_density) {
    const auto foam = states_->elastic_probe() ? physics::without_yield(p.law.ldfoam_params)
                                               : p.law.ldfoam_params;
    if (!A) return physics::ldfoam_update<Dim>(foam, H, old_state, P, new_state, cauchy);
    return ldfoam_stress_and_bound_tangent<Dim>(foam, H, old_state, P, *A, new_state, cauchy);
  }
  if (p.law.foam) {
    const auto foam =
        states_->elastic_probe() ? physics::without_yield(p.law.foam_params) : p.law.foam_params;
    if (!A) return physics::foam_update<Dim>(foam, H, old_state, P, new_state, cauchy);
    return foam_stress_and_elastic_tangent<Dim>(foam, H, old_state, P, *A, new_state, cauchy);
  }
  // Elastic probes (the explicit stable-step estimate) see the elastic predictor here too, as
  // the solid's points do (MaterialStates::elastic_probe).
  const auto law = states_->elastic_probe() ? physics::without_yield(p.law.j2) : p.law.j2;
  if (!A)
    return physics::j2_update<double, Dim>(law, H, old_state, states_->step_time(), P, new_state,
                                           cauchy);
  return j2_stress_and_tangent<Dim>(law, H, old_state, states_->step_time(), P, *A, new_state,
                                    cauchy);
}

template <int Dim>
EssentialConditions::PointState EssentialConditions::evaluate_point(const BoundaryPoint& p,
                                                                    const Vector& d_overlap,
                                                                    BulkTangent bulk) const {
  const std::size_t n = p.nodes.size();
  double H[Dim][Dim] = {}, u[Dim] = {};
  interpolate_at<Dim>(p, d_overlap, u, H);
  double P[Dim][Dim] = {}, A[Dim][Dim][Dim][Dim] = {};
  if (!boundary_stress<Dim>(p, H, P, &A))
    throw NumericalError("det F <= 0 at a boundary point of an essential condition");
  PointState st;
  st.dim = Dim;
  for (int i = 0; i < Dim; ++i) {
    st.gap[i] = p.constrained[static_cast<std::size_t>(i)]
                    ? u[i] - p.value[static_cast<std::size_t>(i)]
                    : 0.0;
    for (int j = 0; j < Dim; ++j)
      st.Pn[i] += P[i][j] * p.weighted_normal[static_cast<std::size_t>(j)];
  }
  st.S.assign(n * Dim * Dim, 0.0);
  for (std::size_t a = 0; a < n; ++a)
    for (int k = 0; k < Dim; ++k)
      for (int i = 0; i < Dim; ++i) {
        double v = 0;
        for (int j = 0; j < Dim; ++j)
          for (int l = 0; l < Dim; ++l)
            v += A[k][j][i][l] * p.grad[a * Dim + static_cast<std::size_t>(l)] *
                 p.weighted_normal[static_cast<std::size_t>(j)];
        st.S[(a * Dim + static_cast<std::size_t>(k)) * Dim + static_cast<std::size_t>(i)] = v;
      }
  if (p.cell_pressure.active())  // mixed u-p: the cell's volumetric stress
    add_cell_pressure_traction<Dim>(p.cell_pressure, p.nodes,
                                    d_overlap.getLocalViewHost(Tpetra::Access::ReadOnly),
                                    p.weighted_normal.data(), st.Pn, st.S, bulk);
  return st;
}

template <int Dim>
void EssentialConditions::point_terms(const BoundaryPoint& p, const Vector& d_overlap,
                                      Vector* r_overlap, FEMatrix* K, std::array<double, 3>* total,
                                      BulkTangent bulk) const {
  const std::size_t n = p.nodes.size();
  const PointState st = evaluate_point<Dim>(p, d_overlap, bulk);
  const bool consistency = p.method != 2, stabilized = p.method != 0, symmetric = p.method == 1;
  if (r_overlap) {
    auto r = r_overlap->getLocalViewHost(Tpetra::Access::ReadWrite);
    for (std::size_t a = 0; a < n; ++a)
      for (int i = 0; i < Dim; ++i) {
        double v = 0;
        if (p.constrained[static_cast<std::size_t>(i)]) {
          if (consistency) v -= p.phi[a] * st.Pn[i];
          if (stabilized) v += p.beta * p.phi[a] * st.gap[i] * p.area;
        }
        if (symmetric)
          for (int k = 0; k < Dim; ++k) v -= st.gap[k] * st.s(a, k, i);
        r(static_cast<std::size_t>(p.nodes[a] * Dim + i), 0) += v;
        if (total) (*total)[static_cast<std::size_t>(i)] += v;
      }
  }
  if (K) {
    // One call per matrix row with all of the point's columns (a call per entry is slow), in
    // sorted order for the local matrix's binary search (as the solid's kernels do): a point of
    // a mixed part reaches its cell's particles too, and Tpetra's unsorted insertion of its
    // hundreds of columns per row made these terms the larger part of a 3D Jacobian's assembly.
    std::vector<int> cols(n * Dim);
    std::vector<std::size_t> slot(n * Dim);  // column (b, k)'s place among the sorted columns
    for (std::size_t e = 0; e < slot.size(); ++e) slot[e] = e;
    const auto column = [&](std::size_t e) {
      return p.nodes[e / Dim] * Dim + static_cast<int>(e % Dim);
    };
    std::sort(slot.begin(), slot.end(),
              [&](std::size_t x, std::size_t y) { return column(x) < column(y); });
    for (std::size_t e = 0; e < slot.size(); ++e) cols[e] = column(slot[e]);
    std::vector<std::size_t> place(slot.size());
    for (std::size_t e = 0; e < slot.size(); ++e) place[slot[e]] = e;
    std::vector<double> vals(n * Dim);
    auto local = K->getLocalMatrixDevice();
    for (std::size_t a = 0; a < n; ++a)
      for (int i = 0; i < Dim; ++i) {
        // Rows of unconstrained components and of particles the point's cell reaches but its
        // supports do not (phi_a = 0) are zero unless the symmetric (Nitsche) term fills them.
        const bool live = p.constrained[static_cast<std::size_t>(i)] && p.phi[a] != 0.0;
        if (!live && !symmetric) continue;
        for (std::size_t b = 0; b < n; ++b)
          for (int k = 0; k < Dim; ++k) {
            double v = 0;
            if (p.constrained[static_cast<std::size_t>(i)]) {
              if (consistency) v -= p.phi[a] * st.s(b, i, k);
              if (stabilized && i == k) v += p.beta * p.phi[a] * p.phi[b] * p.area;
            }
            if (symmetric && p.constrained[static_cast<std::size_t>(k)])
              v -= st.s(a, k, i) * p.phi[b];
            vals[place[b * Dim + static_cast<std::size_t>(k)]] = v;
          }
        local.sumIntoValues(p.nodes[a] * Dim + i, cols.data(), static_cast<int>(cols.size()),
                            vals.data(), true, false);
      }
  }
}

std::shared_ptr<const EssentialConditions::BoundaryTangent> EssentialConditions::boundary_tangent(
    const Vector& d_overlap) const {
  auto tangent = std::make_shared<BoundaryTangent>();
  tangent->points.reserve(points_.size());
  for (const auto& p : points_)
    tangent->points.push_back(dim_ == 2 ? evaluate_point<2>(p, d_overlap)
                                        : evaluate_point<3>(p, d_overlap));
  return tangent;
}

void EssentialConditions::add_boundary_terms(const Vector& d_overlap, Vector& r_overlap,
                                             std::vector<std::array<double, 3>>* totals) const {
  for (const auto& p : points_) {
    auto* total = totals ? &(*totals)[p.condition] : nullptr;
    if (dim_ == 2)
      point_terms<2>(p, d_overlap, &r_overlap, nullptr, total);
    else
      point_terms<3>(p, d_overlap, &r_overlap, nullptr, total);
  }
}

void EssentialConditions::add_boundary_terms(const Vector& d_overlap, FEMatrix& K,
                                             BulkTangent bulk) const {
  for (const auto& p : points_) {
    if (dim_ == 2)
      point_terms<2>(p, d_overlap, nullptr, &K, nullptr, bulk);
    else
      point_terms<3>(p, d_overlap, nullptr, &K, nullptr, bulk);
  }
}

}  // namespace efg
