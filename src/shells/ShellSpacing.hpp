// The particle spacing h a shell's shear stabilization uses (physics with_stabilized_shear): the
// support half-width divided by the dilation, the largest over the directions, i.e. the nodal
// spacing the support was built from (discretization/ParticleCloud).
#pragma once

#include <algorithm>

#include "discretization/ParticleCloud.hpp"

namespace efg {

inline double shell_spacing(const ParticleCloud& cloud, std::size_t particle) {
  const auto& dilation = cloud.section.dilation;
  double h = 0;
  for (int d = 0; d < cloud.dimension; ++d) {
    const double s = dilation.size() > static_cast<std::size_t>(d)
                         ? dilation[static_cast<std::size_t>(d)]
                         : dilation.front();
    h = std::max(h, cloud.a(particle)[d] / s);
  }
  return h;
}

}  // namespace efg
