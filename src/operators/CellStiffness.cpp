#include "operators/CellStiffness.hpp"

#include "mesh/GaussRules.hpp"

namespace efg {

void cell_stiffness(CellType type, const double* x, double lambda, double mu, double scale,
                    std::vector<double>& ke) {
  const int dim = cell_dimension(type), n = cell_node_count(type), size = n * dim;
  ke.assign(static_cast<std::size_t>(size * size), 0.0);
  const auto rule = reference_rule(type, 2);
  double grad[8 * 3];
  for (std::size_t q = 0; q < rule.weight.size(); ++q) {
    const double det = shape_gradients(type, x, &rule.xi[q * static_cast<std::size_t>(dim)], grad);
    const double w = rule.weight[q] * (det < 0 ? -det : det) * scale;
    for (int a = 0; a < n; ++a)
      for (int b = 0; b < n; ++b) {
        const double* ga = grad + a * dim;
        const double* gb = grad + b * dim;
        double dot = 0;
        for (int k = 0; k < dim; ++k) dot += ga[k] * gb[k];
        for (int i = 0; i < dim; ++i)
          for (int j = 0; j < dim; ++j) {
            const double v = lambda * ga[i] * gb[j] + mu * (ga[j] * gb[i] + (i == j ? dot : 0.0));
            ke[static_cast<std::size_t>((a * dim + i) * size + b * dim + j)] += w * v;
          }
      }
  }
}

}  // namespace efg
