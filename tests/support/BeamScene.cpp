#include "support/BeamScene.hpp"

#include <sstream>

namespace efg::test {

std::string beam_scene(int nx, int ny, double perturbation, const char* method, const char* basis,
                       const char* integration, double dilation, const std::string& stage_extra) {
  std::ostringstream s;
  s << "mesh:\n  generate: {element: quad4, lower: [0, -6], upper: [48, 6], cells: [" << nx << ", "
    << ny << "], perturbation: " << perturbation << ", seed: 11}\n"
    << "parts:\n  - {name: beam, blocks: [block_1], material: m, plane: stress, section: {basis: "
    << basis << ", integration: " << integration << ", dilation: " << dilation << "}}\n"
    << "materials:\n  - {name: m, model: linear_elastic, youngs_modulus: 3.0e7, poissons_ratio: "
       "0.3}\n"
    << "boundary_conditions:\n  - {name: clamp, type: displacement, node_set: xmin, "
       "from_exact_solution: [x, y], method: "
    << method << "}\n"
    << "loads:\n  - {name: tip, type: traction, side_set: xmax, from_exact_solution: true}\n"
    << "stages:\n  - {name: load, driver: implicit, end_time: 1" << stage_extra << "}\n"
    << "verification:\n  exact_solution: timoshenko_beam\n  parameters: {length: 48, depth: 12, "
       "load: 1000}\n";
  return s.str();
}

}  // namespace efg::test
