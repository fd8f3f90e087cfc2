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
void FlatShellOperator::point_resultants(std::size_t part, const Point& p, const View& d,
                                         double (&e)[shell_strains],
                                         double (&R)[shell_strains]) const {
  point_strains(p, d, e);
  strain_resultants(part, p, e, R);
}

}  // namespace efg
