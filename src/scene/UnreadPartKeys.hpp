// Keys of a part that its other choices leave unread: `gauss_order` beside an integration other
// than gauss, `smoothing_quadrature` beside gauss or nodal integration (`pressure_cells` beside
// the displacement formulation is refused: PartFormulationCheck). Valid keys, so no error; but a
// user who writes `gauss_order: 4` next to `integration: scni` expects it to do something, and
// should hear that it does not (warnings, with the file, line, column and key path of the key).
#pragma once

#include <yaml-cpp/yaml.h>

#include <string>
#include <vector>

namespace efg {

/// One message per unread key ("FILE:LINE:COL: PATH: ignored: ..."). `written`: the part as in
/// the file (the keys the user wrote); `resolved`: the same part with the schema's defaults;
/// `path`: "parts[i]".
std::vector<std::string> unread_part_keys(const std::string& file, const YAML::Node& written,
                                          const YAML::Node& resolved, const std::string& path);

}  // namespace efg
