#include "support/TestMeshes.hpp"

#include <filesystem>

namespace efg::test {

GeneratorSpec box_spec(CellType element, int n, double perturbation, std::uint64_t seed) {
  GeneratorSpec s;
  s.element = element;
  s.dimension = cell_dimension(element);
  s.lower = {0, 0, 0};
  s.upper = {2, 1, 1};
  s.cells = {2 * n, n, n};
  s.perturbation = perturbation;
  s.seed = seed;
  return s;
}

std::string scratch_dir(const std::string& name) {
  const auto dir = std::filesystem::path(EFG_TEST_TMP) / name;
  std::filesystem::create_directories(dir);
  return dir.string();
}

}  // namespace efg::test
