#include "model/ExactSolutions.hpp"

#include <array>
#include <map>
#include <stdexcept>
#include <vector>

#include <cmath>
#include <set>

#include "core/Errors.hpp"
#include "scene/SchemaValidator.hpp"

namespace efg {
namespace {

// Lame's constants from E and nu (Timoshenko & Goodier): written out here, not taken from the
// physics kernels, so that the exact solutions stay independent oracles of the code they test.
struct Lame {
  double lambda, mu;
};
Lame lame(double e, double nu) {
  return {e * nu / ((1 + nu) * (1 - 2 * nu)), e / (2 * (1 + nu))};
}
// Plane stress: lambda* = E nu / (1 - nu^2).
Lame lame_plane_stress(double e, double nu) {
  return {e * nu / (1 - nu * nu), e / (2 * (1 + nu))};
}

class Parameters {
 public:
  Parameters(const Scene& scene, std::set<std::string> allowed)
      : scene_(scene), node_(scene.verification["parameters"]), allowed_(std::move(allowed)) {
    if (!node_) return;
    for (const auto& kv : node_) {
      const auto key = kv.first.as<std::string>();
      if (!allowed_.count(key)) {
        std::string list;
        for (const auto& a : allowed_) list += (list.empty() ? "" : ", ") + a;
        throw InputError(
            schema::located_message(scene_.file, kv.first, "verification.parameters." + key,
                                    "unknown parameter of exact solution '" +
                                        scene_.exact_solution + "'; allowed: " + list));
      }
    }
  }
  double number(const std::string& key, double fallback) const {
    if (!node_ || !node_[key]) return fallback;
    return value(node_[key], "verification.parameters." + key);
  }
  std::vector<double> numbers(const std::string& key, std::vector<double> fallback) const {
    if (!node_ || !node_[key]) return fallback;
    std::vector<double> v;
    for (const auto& item : node_[key]) v.push_back(value(item, "verification.parameters." + key));
    if (v.size() != fallback.size())
      throw InputError(
          schema::located_message(scene_.file, node_[key], "verification.parameters." + key,
                                  "expected " + std::to_string(fallback.size()) + " numbers"));
    return v;
  }

 private:
  const Scene& scene_;
  YAML::Node node_;
  std::set<std::string> allowed_;

  // A number, or an expression of the scene's parameters (as every number of a scene).
  double value(const YAML::Node& node, const std::string& path) const {
    double v = 0;
    if (node.IsScalar() && node.Tag() != "!" && YAML::convert<double>::decode(node, v)) return v;
    try {
      if (node.IsScalar()) {
        v = Expression(node.Scalar(), scene_.parameters, ExpressionVariables::none)();
        if (std::isfinite(v)) return v;
      }
    } catch (const ExpressionError& e) {
      throw InputError(schema::located_message(
          scene_.file, node, path, std::string("expected a number: ") + e.what(),
          schema::expression_column_offset(node, e.position())));
    }
    throw InputError(schema::located_message(scene_.file, node, path, "expected a number"));
  }
};

// S = lambda tr(g) I + mu (g + g^T) on the first n rows and columns, zero elsewhere (the linear
// elastic stress of a displacement gradient g; plane stress by the reduced lambda).
void linear_elastic_stress(const Lame& c, std::size_t n, const double (&g)[3][3],
                           double (&S)[3][3]) {
  double tr = 0;
  for (std::size_t i = 0; i < n; ++i) tr += g[i][i];
  for (std::size_t i = 0; i < 3; ++i)
    for (std::size_t j = 0; j < 3; ++j)
      S[i][j] = i < n && j < n ? c.mu * (g[i][j] + g[j][i]) + (i == j ? c.lambda * tr : 0.0) : 0.0;
}

const MaterialSpec& first_material(const Scene& s) {
  return *s.find_material(s.parts.front().material);
}

// Timoshenko & Goodier cantilever, plane stress; plane strain by E -> E/(1-nu^2), nu -> nu/(1-nu).
// Domain x in [0, L], y in [-D/2, D/2]; shear traction P at x = L (../shared/reference/benchmarks.md).
ExactSolution timoshenko(const Scene& scene) {
  const Parameters p(scene, {"length", "depth", "load"});
  const double L = p.number("length", 48.0), D = p.number("depth", 12.0),
               P = p.number("load", 1000.0);
  const auto& m = first_material(scene);
  double E = m.constants.at("youngs_modulus"), nu = m.constants.at("poissons_ratio");
  if (!scene.parts.front().plane_stress) {
    E = E / (1 - nu * nu);
    nu = nu / (1 - nu);
  }
  const double I = D * D * D / 12.0;
  ExactSolution s;
  s.name = "timoshenko_beam";
  s.displacement = [=](const double* X, double* u) {
    const double x = X[0], y = X[1];
    u[0] = -P * y / (6 * E * I) * ((6 * L - 3 * x) * x + (2 + nu) * (y * y - D * D / 4));
    u[1] = P / (6 * E * I) *
           (3 * nu * y * y * (L - x) + (4 + 5 * nu) * D * D * x / 4 + (3 * L - x) * x * x);
  };
  s.nominal_stress = [=](const double* X, double(&S)[3][3]) {
    const double x = X[0], y = X[1];
    for (auto& row : S)
      for (auto& v : row) v = 0.0;
    S[0][0] = -P * (L - x) * y / I;
    S[0][1] = S[1][0] = P / (2 * I) * (D * D / 4 - y * y);
  };
  return s;
}

// u = offset + G X with the part's linear elastic stress: the patch test.
ExactSolution linear_patch(const Scene& scene, int dim) {
  const Parameters p(scene, {"gradient", "offset"});
  const auto n = static_cast<std::size_t>(dim);
  std::vector<double> g0(n * n, 0.0), a0(n, 0.0);
  for (std::size_t i = 0; i < n * n; ++i)
    g0[i] = 1e-3 * (1.0 + static_cast<double>(i)) * (i % 2 ? -1.0 : 1.0);
  const auto g = p.numbers("gradient", g0);
  const auto a = p.numbers("offset", a0);
  const auto& m = first_material(scene);
  const bool plane_stress = dim == 2 && scene.parts.front().plane_stress;
  const double e = m.constants.at("youngs_modulus"), nu = m.constants.at("poissons_ratio");
  const auto c = plane_stress ? lame_plane_stress(e, nu) : lame(e, nu);
  ExactSolution s;
  s.name = "linear_patch";
  s.displacement = [=](const double* X, double* u) {
    for (std::size_t i = 0; i < n; ++i) {
      u[i] = a[i];
      for (std::size_t j = 0; j < n; ++j) u[i] += g[i * n + j] * X[j];
    }
  };
  s.nominal_stress = [=](const double*, double(&S)[3][3]) {
    double G[3][3] = {};
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = 0; j < n; ++j) G[i][j] = g[i * n + j];
    linear_elastic_stress(c, n, G, S);
  };
  return s;
}

// u = (F - I) X with F = diag(stretch): a homogeneous deformation of the part's neo-Hookean
// material (the finite-strain patch test); P from the material law.
ExactSolution homogeneous_stretch(const Scene& scene, int dim) {
  const Parameters p(scene, {"stretch"});
  const auto n = static_cast<std::size_t>(dim);
  const auto stretch = p.numbers("stretch", std::vector<double>(n, 1.0));
  for (double l : stretch)
    if (!(l > 0))
      throw InputError(scene.file +
                       ": verification.parameters.stretch: expected positive stretches");
  const auto& m = first_material(scene);
  const auto c = lame(m.constants.at("youngs_modulus"), m.constants.at("poissons_ratio"));
  const bool neo_hookean = m.model == "neo_hookean";
  ExactSolution s;
  s.name = "homogeneous_stretch";
  s.displacement = [=](const double* X, double* u) {
    for (std::size_t i = 0; i < n; ++i) u[i] = (stretch[i] - 1.0) * X[i];
  };
  // F = diag(l_i), J = prod l_i. Neo-Hookean (Bonet & Wood eq. 6.28 with F^-T = diag(1/l_i)):
  // P_ii = mu (l_i - 1/l_i) + lambda ln J / l_i; in 2D plane strain l_3 = 1. Linear elastic:
  // P_ii = lambda tr(eps) + 2 mu eps_ii with eps_ii = l_i - 1. Off-diagonal entries are 0.
  s.nominal_stress = [=](const double*, double(&S)[3][3]) {
    for (auto& row : S)
      for (auto& v : row) v = 0.0;
    double J = 1.0, tr = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      J *= stretch[i];
      tr += stretch[i] - 1.0;
    }
    for (std::size_t i = 0; i < n; ++i) {
      const double l = stretch[i];
      S[i][i] = neo_hookean ? c.mu * (l - 1.0 / l) + c.lambda * std::log(J) / l
                            : c.lambda * tr + 2.0 * c.mu * (l - 1.0);
    }
  };
  return s;
}

// Kambur 2004 ch. 4 / Belytschko, Lu, Gu 1994: u'' + x = 0 on (0, 1), u(0) = 0, u'(1) = 0, so
// u = x/2 - x^3/6 for E A = 1. As a 2D strip (or 3D bar) with nu = 0 the 1D solution is exact:
// u_x = (x/2 - x^3/6) / E under the body force b_x = x, other components zero.
ExactSolution bar_1d(const Scene& scene) {
  const Parameters p(scene, {});
  const auto& m = first_material(scene);
  const double E = m.constants.at("youngs_modulus");
  if (m.constants.at("poissons_ratio") != 0.0)
    throw InputError(scene.file +
                     ": verification.exact_solution: bar_1d is exact for poissons_ratio 0 only");
  ExactSolution s;
  s.name = "bar_1d";
  s.displacement = [=](const double* X, double* u) {
    const double x = X[0];
    u[0] = (x / 2 - x * x * x / 6) / E;
    u[1] = u[2] = 0.0;
  };
  s.nominal_stress = [=](const double* X, double(&S)[3][3]) {
    for (auto& row : S)
      for (auto& v : row) v = 0.0;
    S[0][0] = 0.5 - X[0] * X[0] / 2;
  };
  s.body_force = [](const double* X, double* b) {
    b[0] = X[0];
    b[1] = b[2] = 0.0;
  };
  return s;
}

// verification.user_solution: the scene's expressions of x, y, z (each evaluated at a point padded
// to three coordinates). Without stress expressions the stress is the part's linear elastic
// stress of the displacement gradient, by central differences (step 1e-6 of the point's scale).
ExactSolution user_solution(const Scene& scene, int dim) {
  const auto& spec = *scene.user_solution;
  if (spec.displacement.size() != static_cast<std::size_t>(dim))
    throw InputError(
        spec.displacement.front().where.substr(0, spec.displacement.front().where.rfind('[')) +
        ": expected " + std::to_string(dim) + " expressions for a " + std::to_string(dim) +
        "D mesh, found " + std::to_string(spec.displacement.size()));
  const auto n = static_cast<std::size_t>(dim);
  auto padded = [n](const double* X) {
    std::array<double, 3> p{0, 0, 0};
    for (std::size_t k = 0; k < n; ++k) p[k] = X[k];
    return p;
  };
  ExactSolution s;
  s.name = "user";
  const auto u = spec.displacement;
  s.displacement = [u, n, padded](const double* X, double* out) {
    const auto p = padded(X);
    for (std::size_t k = 0; k < 3; ++k) out[k] = k < n ? u[k].at(p.data(), 0.0) : 0.0;
  };
  if (!spec.stress.empty()) {
    const auto sigma = spec.stress;  // Voigt: xx, yy, zz, yz, xz, xy
    s.nominal_stress = [sigma, padded](const double* X, double(&S)[3][3]) {
      const auto p = padded(X);
      auto v = [&](std::size_t i) { return sigma[i].at(p.data(), 0.0); };
      S[0][0] = v(0), S[1][1] = v(1), S[2][2] = v(2);
      S[1][2] = S[2][1] = v(3), S[0][2] = S[2][0] = v(4), S[0][1] = S[1][0] = v(5);
    };
  } else {
    const auto& m = first_material(scene);
    const bool plane_stress = dim == 2 && scene.parts.front().plane_stress;
    const double e = m.constants.at("youngs_modulus"), nu = m.constants.at("poissons_ratio");
    const auto c = plane_stress ? lame_plane_stress(e, nu) : lame(e, nu);
    ExactSolution u_only;
    u_only.displacement = s.displacement;
    s.nominal_stress = [c, n, u_only](const double* X, double(&S)[3][3]) {
      double g[3][3] = {};
      exact_gradient(u_only, X, n, g);
      linear_elastic_stress(c, n, g, S);
    };
  }
  if (!spec.body_force.empty()) {
    const auto b = spec.body_force;
    s.body_force = [b, n, padded](const double* X, double* out) {
      const auto p = padded(X);
      for (std::size_t k = 0; k < 3; ++k)
        out[k] = k < n && k < b.size() ? b[k].at(p.data(), 0.0) : 0.0;
    };
  }
  return s;
}

}  // namespace

using ExactSolutionBuilder = std::function<ExactSolution(const Scene&, int)>;

// The implementations, by the names of scene/ExactSolutionNames.hpp.
const std::map<std::string, ExactSolutionBuilder>& builders() {
  static const std::map<std::string, ExactSolutionBuilder> table = {
      {"timoshenko_beam",
       [](const Scene& scene, int dimension) {
         if (dimension != 2)
           throw InputError(scene.file +
                            ": verification.exact_solution: timoshenko_beam needs a 2D mesh");
         return timoshenko(scene);
       }},
      {"linear_patch", [](const Scene& scene, int dim) { return linear_patch(scene, dim); }},
      {"bar_1d", [](const Scene& scene, int) { return bar_1d(scene); }},
      {"homogeneous_stretch",
       [](const Scene& scene, int dim) { return homogeneous_stretch(scene, dim); }}};
  return table;
}

void exact_gradient(const ExactSolution& exact, const double* x, std::size_t udim,
                    double (&g)[3][3]) {
  const double h = 1e-6 * (1.0 + std::abs(x[0]));
  for (std::size_t j = 0; j < udim; ++j) {
    double xp[3] = {0, 0, 0}, xm[3] = {0, 0, 0}, up[3], um[3];
    for (std::size_t k = 0; k < udim; ++k) xp[k] = xm[k] = x[k];
    xp[j] += h;
    xm[j] -= h;
    exact.displacement(xp, up);
    exact.displacement(xm, um);
    for (std::size_t i = 0; i < udim; ++i) g[i][j] = (up[i] - um[i]) / (2 * h);
  }
}

std::vector<std::string> implemented_exact_solutions() {
  std::vector<std::string> names;
  for (const auto& entry : builders()) names.push_back(entry.first);
  return names;
}

ExactSolution make_exact_solution(const Scene& scene, int dimension) {
  if (scene.exact_solution == "user") return user_solution(scene, dimension);
  const auto it = builders().find(scene.exact_solution);
  if (it == builders().end())  // the schema offers only implemented names (unit-tested)
    throw std::logic_error("no implementation of exact solution '" + scene.exact_solution + "'");
  return it->second(scene, dimension);
}

}  // namespace efg
