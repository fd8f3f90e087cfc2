// The exact solutions a scene may name (verification.exact_solution). One list: the schema offers
// these choices and model/ExactSolutions.cpp implements each (a unit test checks that the
// implemented set is exactly this one, so that nothing is offered without an implementation).
#pragma once

#include <string>
#include <vector>

namespace efg {

inline const std::vector<std::string>& exact_solution_names() {
  static const std::vector<std::string> names = {"timoshenko_beam", "bar_1d", "homogeneous_stretch",
                                                 "linear_patch"};
  return names;
}

}  // namespace efg
