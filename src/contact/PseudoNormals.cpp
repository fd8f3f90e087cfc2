#include "contact/PseudoNormals.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

#include "geometry/FacetNormal.hpp"

namespace efg::contact {

PseudoNormals::PseudoNormals(const RigidSurface& s) : per_(s.nodes_per_facet) {
  const auto per = static_cast<std::size_t>(per_);
  const std::size_t count = s.count();
  face_.assign(3 * count, 0.0);
  corner_id_.assign(per * count, -1);
  std::map<std::array<double, 3>, int> corners;  // the mesh's nodes, by their coordinates
  for (std::size_t f = 0; f < count; ++f) {
    double x[3][3] = {};
    for (std::size_t a = 0; a < per; ++a) {
      std::array<double, 3> key{};
      for (std::size_t k = 0; k < 3; ++k) x[a][k] = key[k] = s.corners[3 * (per * f + a) + k];
      const auto [it, added] = corners.emplace(key, static_cast<int>(corners.size()));
      corner_id_[per * f + a] = it->second;
    }
    double m[3];
    facet_normal(x, s.dim, m);
    const double size = std::sqrt(m[0] * m[0] + m[1] * m[1] + m[2] * m[2]);
    for (std::size_t k = 0; k < 3; ++k) face_[3 * f + k] = size > 0 ? m[k] / size : 0.0;
  }
  corner_n_.assign(corners.size(), {0.0, 0.0, 0.0});
  for (std::size_t f = 0; f < count; ++f)
    for (std::size_t a = 0; a < per; ++a) {
      // The facet's angle at the corner (Baerentzen & Aanaes, eq. 3); a segment's end: 1.
      double weight = 1.0;
      if (per == 3) {
        const double* p = &s.corners[3 * (per * f + a)];
        const double* q = &s.corners[3 * (per * f + (a + 1) % 3)];
        const double* r = &s.corners[3 * (per * f + (a + 2) % 3)];
        double u[3], v[3];
        for (int k = 0; k < 3; ++k) {
          u[k] = q[k] - p[k];
          v[k] = r[k] - p[k];
        }
        const double uv = u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
        const double uu = u[0] * u[0] + u[1] * u[1] + u[2] * u[2];
        const double vv = v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
        const double cross[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2],
                                 u[0] * v[1] - u[1] * v[0]};
        // atan2 of |u x v| and u . v: accurate for the slivers' angles near 0 and pi.
        weight = uu > 0 && vv > 0 ? std::atan2(std::sqrt(cross[0] * cross[0] + cross[1] * cross[1] +
                                                         cross[2] * cross[2]),
                                               uv)
                                  : 0.0;
      }
      auto& n = corner_n_[static_cast<std::size_t>(corner_id_[per * f + a])];
      for (std::size_t k = 0; k < 3; ++k) n[k] += weight * face_[3 * f + k];
    }
  if (per != 3) return;
  edge_id_.assign(3 * count, -1);
  std::map<std::pair<int, int>, int> edges;
  for (std::size_t f = 0; f < count; ++f)
    for (std::size_t a = 0; a < 3; ++a) {
      const int i = corner_id_[3 * f + a], j = corner_id_[3 * f + (a + 1) % 3];
      const auto [it, added] = edges.emplace(std::make_pair(std::min(i, j), std::max(i, j)),
                                             static_cast<int>(edges.size()));
      edge_id_[3 * f + a] = it->second;
    }
  edge_n_.assign(edges.size(), {0.0, 0.0, 0.0});
  for (std::size_t f = 0; f < count; ++f)
    for (std::size_t a = 0; a < 3; ++a) {
      auto& n = edge_n_[static_cast<std::size_t>(edge_id_[3 * f + a])];
      for (std::size_t k = 0; k < 3; ++k) n[k] += face_[3 * f + k];  // eq. 2: weights pi
    }
}

const double* PseudoNormals::edge(std::size_t f, int local) const {
  if (per_ != 3) return corner(f, local);  // a segment has no edges but its ends
  return edge_n_[static_cast<std::size_t>(edge_id_[3 * f + static_cast<std::size_t>(local)])]
      .data();
}

const double* PseudoNormals::corner(std::size_t f, int local) const {
  const auto per = static_cast<std::size_t>(per_);
  return corner_n_[static_cast<std::size_t>(corner_id_[per * f + static_cast<std::size_t>(local)])]
      .data();
}

}  // namespace efg::contact
