#include "run/Probes.hpp"

#include "tensor/Tensor.hpp"

#include <Teuchos_CommHelpers.hpp>

#include <limits>
#include <sstream>

#include "discretization/ShapeFunctions.hpp"
#include "model/GradedMaterials.hpp"
#include "model/MaterialLaws.hpp"
#include "model/PointOwner.hpp"

namespace efg {
namespace {

const char* tensor_components(int dim) {
  return dim == 2 ? "xx yy xy" : "xx yy zz yz xz xy";
}

std::vector<std::pair<int, int>> tensor_indices(int dim) {
  if (dim == 2) return {{0, 0}, {1, 1}, {0, 1}};
  return {{0, 0}, {1, 1}, {2, 2}, {1, 2}, {0, 2}, {0, 1}};
}

// Stress columns only when every part's law is elastic (a plastic law's stress needs the
// history of a point that has none).
bool elastic_parts(const Scene& scene) {
  for (const auto& part : scene.parts)
    if (scene.find_material(part.material)->path_dependent()) return false;
  return true;
}

template <int Dim>
void stress_at(const physics::SolidMaterial& m, const double (&g)[3][3], double (&s)[3][3]) {
  double H[Dim][Dim], P[Dim][Dim] = {};  // stays 0 at an inverted point (det F <= 0)
  for (int i = 0; i < Dim; ++i)
    for (int j = 0; j < Dim; ++j) H[i][j] = g[i][j];
  physics::stress<Dim>(m, H, P);
  for (int i = 0; i < Dim; ++i)
    for (int j = 0; j < Dim; ++j) s[i][j] = P[i][j];
}

// The pressure p (compression positive, Cauchy) in the probe's stress s: -p I for small strain,
// -p J F^-T in the first Piola-Kirchhoff stress of a total Lagrangian part (F = I + g).
void add_pressure(double (&s)[3][3], const double (&g)[3][3], int dim, double p, bool finite) {
  if (!finite) {
    for (int a = 0; a < 3; ++a) s[a][a] -= p;
    return;
  }
  double F[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, Finv[3][3];
  for (int i = 0; i < dim; ++i)
    for (int j = 0; j < dim; ++j) F[i][j] += g[i][j];
  const double J = physics::determinant<3>(F);
  if (!(J > 0)) return;
  physics::inverse<3>(F, J, Finv);
  for (int i = 0; i < dim; ++i)
    for (int j = 0; j < dim; ++j) s[i][j] -= p * J * Finv[j][i];
}

}  // namespace

std::vector<std::string> probe_names(const Scene& scene, int dimension) {
  std::vector<std::string> names;
  const std::string axes = "xyz";
  const bool stress = elastic_parts(scene);
  for (const auto& probe : scene.probes) {
    const auto prefix = "probe_" + probe.name + "_";
    for (int d = 0; d < dimension; ++d)
      names.push_back(prefix + "u" + axes[static_cast<std::size_t>(d)]);
    for (const char* kind : {"e", "s"}) {
      if (*kind == 's' && !stress) continue;
      std::istringstream components(tensor_components(dimension));
      for (std::string c; components >> c;) names.push_back(prefix + kind + c);
    }
  }
  return names;
}

std::vector<double> probe_values(const Model& model, const SolidOperator& op,
                                 const Vector& d_overlap, const MixedPressure* mixed) {
  const int dim = model.mesh.dimension;
  const auto udim = static_cast<std::size_t>(dim);
  const bool with_stress = elastic_parts(model.scene);
  const auto pairs = tensor_indices(dim);
  const std::size_t per_probe = udim + pairs.size() * (with_stress ? 2 : 1);
  std::vector<double> local(per_probe * model.scene.probes.size(), 0.0);
  const auto pressure = mixed && with_stress && !model.scene.probes.empty()
                            ? mixed->overlap_pressures(d_overlap)
                            : std::vector<double>{};
  const auto d = d_overlap.getLocalViewHost(Tpetra::Access::ReadOnly);
  for (std::size_t i = 0; i < model.scene.probes.size(); ++i) {
    const auto& probe = model.scene.probes[i];
    const int p = evaluating_part(model, probe.point.data());
    if (p < 0) continue;
    const auto part = static_cast<std::size_t>(p);
    const auto v =
        evaluate_shape_functions(model.parts[part].cloud, probe.point.data(), 1, true,
                                 [&](std::size_t) { return "probe '" + probe.name + "'"; });
    double u[3] = {0, 0, 0}, g[3][3] = {}, p_probe = 0;
    for (auto k = v.neighbors.offsets[0]; k < v.neighbors.offsets[1]; ++k) {
      const auto n = static_cast<std::size_t>(
          op.overlap_node(part)[static_cast<std::size_t>(v.neighbors.particles[k])]);
      if (!pressure.empty()) p_probe += v.phi[k] * pressure[n];
      for (std::size_t a = 0; a < udim; ++a) {
        u[a] += v.phi[k] * d(n * udim + a, 0);
        for (std::size_t b = 0; b < udim; ++b) g[a][b] += d(n * udim + a, 0) * v.grad[k * udim + b];
      }
    }
    double* out = &local[i * per_probe];
    for (std::size_t a = 0; a < udim; ++a) *out++ = u[a];
    for (const auto& [a, b] : pairs) *out++ = 0.5 * (g[a][b] + g[b][a]);
    if (!with_stress) continue;
    auto law = material_law(model.scene, *model.parts[part].part, dim);
    const auto scale = modulus_scale(*model.scene.find_material(model.parts[part].part->material),
                                     probe.point.data(), 1, 3);
    if (!scale.empty())  // graded material: E at the probe
      law.elastic = physics::with_moduli_scaled(law.elastic, scale[0]);
    double s[3][3] = {};
    if (dim == 2)
      stress_at<2>(law.elastic, g, s);
    else
      stress_at<3>(law.elastic, g, s);
    if (law.mixed())  // law.elastic is the deviatoric part (model/MaterialLaws)
      add_pressure(s, g, dim, p_probe,
                   model.parts[part].part->section.formulation != Formulation::small_strain);
    for (const auto& [a, b] : pairs) *out++ = s[a][b];
  }
  std::vector<double> global(local.size(), 0.0);
  if (!local.empty())
    Teuchos::reduceAll(*model.maps.owned_dofs->getComm(), Teuchos::REDUCE_SUM,
                       static_cast<int>(local.size()), local.data(), global.data());
  return global;
}

}  // namespace efg
