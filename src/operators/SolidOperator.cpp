#include "operators/SolidOperator.hpp"

#include <Teuchos_TimeMonitor.hpp>

#include <algorithm>
#include <sstream>
#include <type_traits>

#include "core/Errors.hpp"
#include "materials/ElasticConstants.hpp"
#include "operators/StiffnessBound.hpp"
#include "parallel/ReproducibleSum.hpp"

namespace efg {
namespace {

auto column(const Vector& v) {
  return Kokkos::subview(v.getLocalViewDevice(Tpetra::Access::ReadOnly), Kokkos::ALL(), 0);
}
auto column(Vector& v) {
  return Kokkos::subview(v.getLocalViewDevice(Tpetra::Access::ReadWrite), Kokkos::ALL(), 0);
}

}  // namespace

SolidOperator::SolidOperator(const Model& model) : dim_(model.mesh.dimension), history_(model) {
  const auto& overlap = *model.maps.overlap_nodes;
  overlap_nodes_ = overlap.getNodeNumElements();
  for (const auto& d : model.parts) {
    PartData p;
    p.name = d.part->name;
    for (auto node : d.cloud.mesh_node) {
      const auto lid = overlap.getLocalElement(global_node_id(model, node));
      if (lid == Teuchos::OrdinalTraits<int>::invalid())
        throw std::logic_error("particle missing from the overlap map");
      p.overlap_node.push_back(lid);
    }
    const auto& ip = d.points;
    const double thickness = dim_ == 2 ? d.part->thickness : 1.0;
    std::vector<double> weight(ip.weight);
    for (auto& w : weight) w *= thickness;
    std::vector<int> node;
    for (auto particle : ip.gradients.particles)
      node.push_back(p.overlap_node[static_cast<std::size_t>(particle)]);
    // The gradient table and its offsets are read where the discretization keeps them (the model
    // outlives its operators): on a host execution space no second copy (docs/scaling.md).
    p.device.weight = to_device(weight, "efg::solid weight");
    p.device.offsets = device_view_of(ip.gradients.offsets, "efg::solid offsets");
    p.device.node = to_device(node, "efg::solid node");
    p.device.grad = device_view_of(ip.gradients.values, ip.gradients.particles.size(),
                                   static_cast<std::size_t>(dim_), "efg::solid grad");
    p.device.by_node = gather_index(p.device.offsets, p.device.node, overlap_nodes_);
    p.slot_count = ip.gradients.particles.size();
    DeviceView<int*> slot(Kokkos::view_alloc(Kokkos::WithoutInitializing, "efg::solid slots"),
                          p.slot_count);
    const auto entry = p.device.by_node.entry;
    Kokkos::parallel_for(
        "efg::solid_slots", Kokkos::RangePolicy<ExecSpace>(0, p.slot_count),
        KOKKOS_LAMBDA(const std::size_t e) { slot(entry(e)) = static_cast<int>(e); });
    p.device.slot = slot;
    const auto& states = history_.part(parts_.size());
    const MaterialLaw& law = states.law;
    p.device.material = PointMaterial{law.elastic,
                                      law.plastic,
                                      law.j2,
                                      states.committed,
                                      states.trial,
                                      0.0,
                                      states.modulus_scale,
                                      states.modulus_scale.extent(0) > 0,
                                      law.foam,
                                      law.foam_params,
                                      law.low_density,
                                      law.ldfoam_params};
    p.small_strain = d.part->section.formulation == Formulation::small_strain;
    p.points = ip.size();
    p.x = ip.x;
    p.node = ip.node;
    p.domain = ip.domain;
    if (!p.domain.empty()) p.weight = ip.weight;
    parts_.push_back(std::move(p));
  }
}

void SolidOperator::add_point_couplings(CouplingGraph& graph) const {
  for (const auto& p : parts_) {
    auto offsets = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), p.device.offsets);
    auto node = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), p.device.node);
    for (std::size_t q = 0; q < p.points; ++q)
      graph.add_clique(node.data() + offsets(q), offsets(q + 1) - offsets(q));
  }
}

std::string SolidOperator::point_location(const PartData& part, int point) const {
  std::ostringstream o;
  if (part.node[static_cast<std::size_t>(point)] >= 0)
    o << "the integration point of particle " << part.node[static_cast<std::size_t>(point)] + 1;
  else if (!part.domain.empty())
    o << "a subcell point of particle " << part.domain[static_cast<std::size_t>(point)] + 1;
  else
    o << "a Gauss point";
  o << " at (";
  for (int d = 0; d < dim_; ++d)
    o << (d ? ", " : "") << part.x[static_cast<std::size_t>(point * dim_ + d)];
  o << ")";
  return o.str();
}

void SolidOperator::report_inversion(const PartData& part, int point) const {
  throw NumericalError("part '" + part.name + "': det F <= 0 (inverted material) at " +
                       point_location(part, point));
}

template <class Pass1, class Gather>
void SolidOperator::for_each_part(const Pass1& pass1, const Gather& gather) const {
  for (const auto& p : parts_) {
    Kokkos::View<int, MemSpace> inverted("efg::inverted");
    Kokkos::deep_copy(inverted, INT_MAX);
    const auto points = Kokkos::RangePolicy<ExecSpace>(0, static_cast<int>(p.points));
    if (dim_ == 2)
      pass1(std::integral_constant<int, 2>(), points, p, inverted);
    else
      pass1(std::integral_constant<int, 3>(), points, p, inverted);
    int bad = INT_MAX;
    Kokkos::deep_copy(bad, inverted);
    if (bad != INT_MAX) report_inversion(p, bad);
    const auto nodes = Kokkos::RangePolicy<ExecSpace>(0, static_cast<int>(overlap_nodes_));
    if (dim_ == 2)
      gather(std::integral_constant<int, 2>(), nodes, p);
    else
      gather(std::integral_constant<int, 3>(), nodes, p);
  }
}

void SolidOperator::add_internal_force(const Vector& d_overlap, Vector& f_overlap) const {
  Teuchos::TimeMonitor timer(*Teuchos::TimeMonitor::getNewCounter("efg: internal force"));
  const auto u = column(d_overlap);
  auto f = column(f_overlap);
  if constexpr (std::is_same_v<ExecSpace, Kokkos::Serial>) {
    // One thread: the one-pass scatter gives the gather's bits, faster (SerialForceKernel).
    for_each_part(
        [&](auto dim, const auto& points, const PartData& p, const auto& inverted) {
          using Kernel = SerialForceKernel<decltype(dim)::value, decltype(u), decltype(f)>;
          Kokkos::parallel_for("efg::internal_force", points, Kernel{device(p), u, f, inverted});
        },
        [](auto, const auto&, const PartData&) {});
    return;
  }
  for_each_part(
      [&](auto dim, const auto& points, const PartData& p, const auto& inverted) {
        constexpr int Dim = decltype(dim)::value;
        if (p.term.extent(0) != p.slot_count)
          p.term = DeviceView<double**>("efg::force terms", p.slot_count, Dim);
        Kokkos::parallel_for("efg::point_force", points,
                             PointForceKernel<Dim, decltype(u)>{device(p), u, p.term, inverted});
      },
      [&](auto dim, const auto& nodes, const PartData& p) {
        using Kernel = NodalForceKernel<decltype(dim)::value, decltype(f)>;
        Kokkos::parallel_for("efg::internal_force", nodes, Kernel{device(p), p.term, f});
      });
}

void SolidOperator::add_tangent(const Vector& d_overlap, FEMatrix& K) const {
  Teuchos::TimeMonitor timer(*Teuchos::TimeMonitor::getNewCounter("efg: tangent assembly"));
  const auto u = column(d_overlap);
  auto local = K.getLocalMatrixDevice();
  for_each_part(
      [&](auto dim, const auto& points, const PartData& p, const auto& inverted) {
        constexpr int Dim = decltype(dim)::value;
        if (p.tangent.extent(0) != p.points)
          p.tangent = DeviceView<double**>("efg::point tangent", p.points, Dim * Dim * Dim * Dim);
        Kokkos::parallel_for(
            "efg::point_tangent", points,
            PointTangentKernel<Dim, decltype(u)>{device(p), u, p.tangent, inverted});
      },
      [&](auto dim, const auto& nodes, const PartData& p) {
        using Kernel = NodalTangentKernel<decltype(dim)::value, decltype(local)>;
        Kokkos::parallel_for("efg::tangent", nodes, Kernel{device(p), p.tangent, local});
      });
}

void SolidOperator::add_stiffness_row_bound(const Vector& d_overlap, Vector& c_overlap) const {
  const auto u = column(d_overlap);
  auto c = column(c_overlap);
  for_each_part(
      [&](auto dim, const auto& points, const PartData& p, const auto& inverted) {
        constexpr int Dim = decltype(dim)::value;
        if (p.term.extent(0) != p.slot_count)
          p.term = DeviceView<double**>("efg::force terms", p.slot_count, Dim);
        Kokkos::parallel_for(
            "efg::point_stiffness_bound", points,
            PointStiffnessBoundKernel<Dim, decltype(u)>{device(p), u, p.term, inverted});
      },
      [&](auto dim, const auto& nodes, const PartData& p) {
        using Kernel = NodalStiffnessBoundKernel<decltype(dim)::value, decltype(c)>;
        Kokkos::parallel_for("efg::stiffness_bound", nodes, Kernel{device(p), p.term, c});
      });
}

double SolidOperator::largest_gradient(const Vector& delta_overlap, const Vector& d_overlap) const {
  const auto u = column(delta_overlap);
  const auto x = column(d_overlap);
  double largest = 0;
  for (const auto& p : parts_) {
    if (p.small_strain) continue;
    const auto points = Kokkos::RangePolicy<ExecSpace>(0, static_cast<int>(p.points));
    const DevicePoints d = p.device;
    double part_largest = 0;
    auto reduce = [&](auto dim) {
      constexpr int Dim = decltype(dim)::value;
      Kokkos::parallel_reduce(
          "efg::largest_gradient", points,
          KOKKOS_LAMBDA(const int q, double& m) {
            // An eroded point is out of the model: its strain changes no stiffness.
            if (d.material.plastic && d.material.committed(q, physics::j2_state::eroded) > 0.5)
              return;
            double H[Dim][Dim], F[Dim][Dim], F_inv[Dim][Dim];
            displacement_gradient<Dim>(d, x, q, F);
            for (int i = 0; i < Dim; ++i) F[i][i] += 1.0;
            const double J = physics::determinant<Dim>(F);
            if (!(J > 0)) {
              m = 1e300;  // inverted: re-estimate at once (the fold guard names it)
              return;
            }
            physics::inverse<Dim>(F, J, F_inv);
            displacement_gradient<Dim>(d, u, q, H);
            for (int i = 0; i < Dim; ++i)
              for (int j = 0; j < Dim; ++j) {
                double L = 0.0;  // (grad_X delta F^-1)_ij = d delta_i / d x_j
                for (int k = 0; k < Dim; ++k) L += H[i][k] * F_inv[k][j];
                m = fabs(L) > m ? fabs(L) : m;
              }
          },
          Kokkos::Max<double>(part_largest));
    };
    if (dim_ == 2)
      reduce(std::integral_constant<int, 2>());
    else
      reduce(std::integral_constant<int, 3>());
    largest = std::max(largest, part_largest);
  }
  return largest;
}

double SolidOperator::check_small_strain(const Vector& d_overlap, double time) const {
  const auto u = column(d_overlap);
  double largest = 0;
  for (const auto& p : parts_) {
    if (!p.small_strain) continue;
    DeviceView<double**> out("efg::kinematics", p.points, 2);
    const auto points = Kokkos::RangePolicy<ExecSpace>(0, static_cast<int>(p.points));
    if (dim_ == 2)
      Kokkos::parallel_for("efg::kinematics", points,
                           PointKinematics<2, decltype(u)>{device(p), u, out});
    else
      Kokkos::parallel_for("efg::kinematics", points,
                           PointKinematics<3, decltype(u)>{device(p), u, out});
    const auto host = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), out);
    for (std::size_t q = 0; q < p.points; ++q) {
      if (!(host(q, 0) > 0)) {
        std::ostringstream o;
        o << "part '" << p.name
          << "': particles passed through each other: det(I + grad u) = " << host(q, 0)
          << " <= 0 at " << point_location(p, static_cast<int>(q)) << ", t = " << time
          << "; a small-strain formulation cannot represent this motion (use formulation "
             "total_lagrangian: model neo_hookean, or j2_plasticity at finite strain)";
        throw NumericalError(o.str());
      }
      largest = std::max(largest, host(q, 1));
    }
  }
  return largest;
}

std::vector<SolidOperator::HistoryOutput> SolidOperator::history_output(
    const Vector& d_overlap) const {
  const auto u = column(d_overlap);
  std::vector<HistoryOutput> result(parts_.size());
  for (std::size_t i = 0; i < parts_.size(); ++i) {
    const auto& p = parts_[i];
    if (!p.device.material.plastic) continue;
    DeviceView<double**> out("efg::history output", p.points, history_columns);
    const auto points = Kokkos::RangePolicy<ExecSpace>(0, static_cast<int>(p.points));
    if (dim_ == 2)
      Kokkos::parallel_for("efg::history_output", points,
                           PointHistoryOutput<2, decltype(u)>{device(p), u, out});
    else
      Kokkos::parallel_for("efg::history_output", points,
                           PointHistoryOutput<3, decltype(u)>{device(p), u, out});
    const auto host = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), out);
    result[i].node = p.node;
    result[i].domain = p.domain;
    result[i].weight = p.weight;
    result[i].values.assign(host.data(), host.data() + p.points * history_columns);
  }
  return result;
}

long long SolidOperator::eroded_points() const {
  long long total = 0;
  for (const auto& p : parts_) {
    if (!p.device.material.plastic) continue;
    const auto committed = p.device.material.committed;
    long long part = 0;
    Kokkos::parallel_reduce(
        "efg::eroded_points", Kokkos::RangePolicy<ExecSpace>(0, p.points),
        KOKKOS_LAMBDA(const std::size_t q, long long& n) {
          if (committed(q, physics::j2_state::eroded) > 0.5) ++n;
        },
        part);
    total += part;
  }
  return total;
}

double SolidOperator::eroded_energy() const {
  double total = 0;
  for (const auto& p : parts_)
    if (p.device.material.plastic) total += block_sum(p.points, PointErodedEnergy{p.device});
  return total;
}

double SolidOperator::strain_energy(const Vector& d_overlap) const {
  const auto u = column(d_overlap);
  double total = 0;
  for (const auto& p : parts_) {
    if (dim_ == 2)
      total += block_sum(p.points, PointEnergy<2, decltype(u)>{device(p), u});
    else
      total += block_sum(p.points, PointEnergy<3, decltype(u)>{device(p), u});
  }
  return total;
}

}  // namespace efg
