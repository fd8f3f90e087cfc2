// Reads background meshes (and, for tests and tools, stored results) from Exodus II files.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "mesh/BackgroundMesh.hpp"

namespace efg {

/// Reads coordinates, element blocks, node sets, side sets and their names. Unnamed entities get
/// "block_<id>", "nodeset_<id>", "sideset_<id>". Throws InputError on anything unreadable or
/// unsupported. The mesh is not validated here: see validate_mesh().
BackgroundMesh read_exodus_mesh(const std::string& path);

/// Results stored in an Exodus file: one entry per time step.
struct ExodusResults {
  std::vector<double> times;
  std::map<std::string, std::vector<std::vector<double>>> nodal;    ///< name -> step -> node
  std::map<std::string, std::vector<std::vector<double>>> element;  ///< name -> step -> cell
  std::map<std::string, std::vector<double>> global;                ///< name -> step
};
ExodusResults read_exodus_results(const std::string& path);

}  // namespace efg
