// The point law of FlatShellOperator, shared by its two source files: the generalized strains of
// an integration point and its resultants N, M, Q (elastic section, or J2 through the thickness
// with the layers' trial states written). Templates on the view of the overlap values; included
// by shells/FlatShellOperator.cpp and shells/FlatShellResponse.cpp only.
#pragma once

#include "materials/ShellSectionJ2.hpp"
#include "shells/FlatShellOperator.hpp"

namespace efg {

template <class View>
void FlatShellOperator::finite_point(const Point& p, const View& d, FinitePoint& fp) const {
  fp.nodes.clear();
  fp.geometry = reference_geometry();
  for (std::size_t a = 0; a < p.node.size(); ++a) {
    fp.nodes.push_back(node_at(p.node[a], &p.b[2 * a], &p.g[2 * a], p.phi[a], d));
    add_to_geometry(fp.nodes.back(), fp.geometry);
  }
}

template <class View>
void FlatShellOperator::point_strains(const Point& p, const View& d,
                                      double (&e)[shell_strains]) const {
  if (finite_) {
    FinitePoint fp;
    finite_point(p, d, fp);
    return finite_strains(p, fp, e);
  }
  for (auto& v : e) v = 0;
  for (std::size_t a = 0; a < p.node.size(); ++a) {
    double B[shell_strains][shell_dofs_per_node];
    plate_strain_rows({p.b[2 * a], p.b[2 * a + 1]}, {p.g[2 * a], p.g[2 * a + 1]}, p.phi[a], B);
    for (std::size_t c = 0; c < shell_dofs_per_node; ++c) {
      const double dc = d(static_cast<std::size_t>(p.node[a]) * shell_dofs_per_node + c, 0);
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

}  // namespace efg
