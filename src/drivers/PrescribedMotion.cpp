#include "drivers/PrescribedMotion.hpp"

#include <Teuchos_CommHelpers.hpp>

#include <set>

#include "parallel/ReproducibleSum.hpp"

namespace efg {

PrescribedMotion::PrescribedMotion(const Model& model, const std::string& stage)
    : conditions_(model.scene.boundary_conditions.size()) {
  const int dim = model.mesh.dimension;
  std::set<int> taken;
  for (std::size_t b = 0; b < conditions_; ++b) {
    const auto& bc = model.scene.boundary_conditions[b];
    // Displacement conditions with method nitsche or penalty act weakly (drivers/WeakSupports).
    if (bc.type == "displacement" && bc.method != "transformation") continue;
    if (!bc.stages.includes(stage)) continue;  // released in this stage
    for (auto node : model.mesh.find_node_set(bc.node_set)->nodes) {
      if (model.partition.owner[static_cast<std::size_t>(node)] != model.partition.rank) continue;
      for (int i = 0; i < dim; ++i) {
        const auto& c = bc.components[static_cast<std::size_t>(i)];
        if (!c) continue;  // values from an exact solution are for static verification
        const int row =
            model.maps.owned_dofs->getLocalElement(global_node_id(model, node) * dim + i);
        if (taken.insert(row).second) {
          Dof dof{row, b, i, bc.type == "velocity", &*c, {}, bc.curve};
          for (int k = 0; k < dim; ++k)
            dof.X[static_cast<std::size_t>(k)] =
                model.mesh.coordinates[static_cast<std::size_t>(node * dim + k)];
          dofs_.push_back(dof);
        }
      }
    }
  }
  rows_.assign(taken.begin(), taken.end());
}

std::vector<std::array<double, 3>> PrescribedMotion::reactions(const Vector& R) const {
  std::vector<double> local(3 * conditions_, 0.0), global(3 * conditions_, 0.0);
  const auto r = R.getLocalViewHost(Tpetra::Access::ReadOnly);
  for (const auto& c : dofs_)
    local[3 * c.condition + static_cast<std::size_t>(c.direction)] +=
        r(static_cast<std::size_t>(c.row), 0);
  if (!local.empty())
    Teuchos::reduceAll(*R.getMap()->getComm(), Teuchos::REDUCE_SUM, static_cast<int>(local.size()),
                       local.data(), global.data());
  std::vector<std::array<double, 3>> out(conditions_);
  for (std::size_t c = 0; c < conditions_; ++c)
    out[c] = {global[3 * c], global[3 * c + 1], global[3 * c + 2]};
  return out;
}

void PrescribedMotion::constrain_velocity(const LoadFactor& start, const LoadFactor& mid,
                                          const LoadFactor& end, double dt, Vector& v_half) const {
  auto v = v_half.getLocalViewHost(Tpetra::Access::ReadWrite);
  for (const auto& c : dofs_) {
    const auto k = static_cast<std::size_t>(c.row);
    v(k, 0) = c.velocity ? c.at(mid) : (c.at(end) - c.at(start)) / dt;
  }
}

void PrescribedMotion::constrain_end(const LoadFactor& end, const Vector& v_half, Vector& v_end,
                                     Vector& a_end) const {
  auto v = v_end.getLocalViewHost(Tpetra::Access::ReadWrite);
  auto a = a_end.getLocalViewHost(Tpetra::Access::ReadWrite);
  const auto rate = v_half.getLocalViewHost(Tpetra::Access::ReadOnly);
  for (const auto& c : dofs_) {
    const auto k = static_cast<std::size_t>(c.row);
    a(k, 0) = 0.0;
    v(k, 0) = c.velocity ? c.at(end) : rate(k, 0);
  }
}

void PrescribedMotion::support_force(const Vector& mass, const Vector& a_free, Vector& R,
                                     bool rows_only) const {
  if (!rows_only) R.putScalar(0.0);
  auto r = R.getLocalViewHost(Tpetra::Access::ReadWrite);
  const auto m = mass.getLocalViewHost(Tpetra::Access::ReadOnly);
  const auto a = a_free.getLocalViewHost(Tpetra::Access::ReadOnly);
  for (const auto& c : dofs_) {
    const auto k = static_cast<std::size_t>(c.row);
    r(k, 0) = -m(k, 0) * a(k, 0);
  }
}

double PrescribedMotion::kinetic_energy_change(const Vector& mass, const Vector& v_start,
                                               const Vector& v_end) const {
  const auto m = mass.getLocalViewHost(Tpetra::Access::ReadOnly);
  const auto v0 = v_start.getLocalViewHost(Tpetra::Access::ReadOnly);
  const auto v1 = v_end.getLocalViewHost(Tpetra::Access::ReadOnly);
  double mine = 0.0, all = 0.0;
  for (const auto& c : dofs_) {
    const auto k = static_cast<std::size_t>(c.row);
    mine += 0.5 * m(k, 0) * (v1(k, 0) * v1(k, 0) - v0(k, 0) * v0(k, 0));
  }
  Teuchos::reduceAll(*mass.getMap()->getComm(), Teuchos::REDUCE_SUM, mine, Teuchos::outArg(all));
  return all;
}

std::array<double, 2> PrescribedMotion::support_work(const Vector& R_old, const Vector& R_new,
                                                     const Vector& delta) const {
  const auto r0 = R_old.getLocalViewHost(Tpetra::Access::ReadOnly);
  const auto r1 = R_new.getLocalViewHost(Tpetra::Access::ReadOnly);
  const auto dd = delta.getLocalViewHost(Tpetra::Access::ReadOnly);
  // reproducible_dot's order: a block's terms in index order from +0 (the zeros between leave
  // a partial sum as it is: it is never -0), then the block sums in order (a block without
  // constrained rows adds +0).
  std::array<double, 2> mine{}, block{}, all{};
  std::size_t current = 0;
  bool open = false;
  for (const int row : rows_) {
    const auto k = static_cast<std::size_t>(row);
    if (open && k / block_size != current) {
      for (std::size_t i = 0; i < 2; ++i) mine[i] += block[i];
      block = {};
    }
    current = k / block_size;
    open = true;
    block[0] += r0(k, 0) * dd(k, 0);
    block[1] += r1(k, 0) * dd(k, 0);
  }
  if (open)
    for (std::size_t i = 0; i < 2; ++i) mine[i] += block[i];
  Teuchos::reduceAll(*delta.getMap()->getComm(), Teuchos::REDUCE_SUM, 2, mine.data(), all.data());
  return all;
}

}  // namespace efg
