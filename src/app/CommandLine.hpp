// The efg command line: `efg run|check|mesh|schema ...`, `efg --help`, `efg --version`.
#pragma once

#include <string>
#include <vector>

namespace efg {

struct CommandLine {
  std::string command;              ///< run, check, mesh, schema, help, version
  std::string scene;                ///< scene file (run, check, mesh)
  std::string output_dir;           ///< run: -o/--output, default "."
  std::string mesh_output;          ///< mesh: the Exodus file to write
  int levels = 4;                   ///< study: refinement levels
  double factor = 2.0;              ///< study: refinement factor per level
  std::vector<std::string> sweeps;  ///< study: KEY=V1,V2,...
  int threads = 0;  ///< --threads N per rank (0: OMP_NUM_THREADS or the backend's default)
};

/// Throws InputError with a usage hint on a malformed command line.
CommandLine parse_command_line(const std::vector<std::string>& args);

/// The text of `efg --help`.
std::string help_text();

}  // namespace efg
