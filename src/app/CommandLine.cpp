#include "app/CommandLine.hpp"

#include "core/Errors.hpp"

namespace efg {
namespace {
[[noreturn]] void usage_error(const std::string& what) {
  throw InputError("command line: " + what + " (see 'efg --help')");
}
}  // namespace

std::string help_text() {
  return R"(efg: Element-Free Galerkin solver for solids under large deformation

Usage:
  efg run SCENE.yaml [-o OUTDIR]   run a scene; results go to OUTDIR (default: the current folder)
  efg check SCENE.yaml             validate the scene and its mesh, print the resolved scene
  efg mesh SCENE.yaml OUT.exo      write the scene's background mesh (generated or read) as Exodus II
  efg schema                       print the scene file reference (docs/scene.md)
  efg --help                       this text
  efg --version                    version and git revision

Parallel: mpirun -np N efg run SCENE.yaml distributes the particles over N ranks.

Exit codes:
  0  success
  1  any other failure (I/O error, internal error, unavailable feature)
  2  bad input: command line, scene file or mesh file (nothing is written)
  3  numerical failure (singular moment matrix, unstable time step, negative Jacobian, NaN,
     Newton divergence), reported with particle, step and time
)";
}

CommandLine parse_command_line(const std::vector<std::string>& args) {
  CommandLine cl;
  if (args.empty()) usage_error("no command given");
  const auto& first = args[0];
  if (first == "--help" || first == "-h" || first == "help") {
    cl.command = "help";
    return cl;
  }
  if (first == "--version" || first == "-V") {
    cl.command = "version";
    return cl;
  }
  if (first != "run" && first != "check" && first != "mesh" && first != "schema")
    usage_error("unknown command '" + first + "'; expected run, check, mesh, schema, --help or --version");
  cl.command = first;
  std::vector<std::string> positional;
  for (std::size_t i = 1; i < args.size(); ++i) {
    const auto& a = args[i];
    if (a == "-o" || a == "--output") {
      if (cl.command != "run") usage_error("option " + a + " belongs to 'efg run'");
      if (i + 1 >= args.size()) usage_error("option " + a + " needs a folder");
      cl.output_dir = args[++i];
    } else if (!a.empty() && a[0] == '-') {
      usage_error("unknown option '" + a + "' for 'efg " + cl.command + "'");
    } else {
      positional.push_back(a);
    }
  }
  const std::size_t expected = cl.command == "schema" ? 0 : (cl.command == "mesh" ? 2 : 1);
  if (positional.size() != expected) {
    const std::string what = cl.command == "schema" ? "no arguments" : (cl.command == "mesh" ? "SCENE.yaml OUT.exo" : "one SCENE.yaml");
    usage_error("'efg " + cl.command + "' expects " + what + ", got " + std::to_string(positional.size()) + " argument(s)");
  }
  if (expected >= 1) cl.scene = positional[0];
  if (expected == 2) cl.mesh_output = positional[1];
  if (cl.output_dir.empty()) cl.output_dir = ".";
  return cl;
}

}  // namespace efg
