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
  efg check SCENE.yaml [-o OUTDIR] validate the scene, its mesh and its output paths (nothing is
                                   written), print the resolved scene
  efg mesh SCENE.yaml OUT.exo      write the scene's background mesh (generated or read) as Exodus II
  efg study SCENE.yaml [-o OUTDIR] [--levels N] [--factor F] [--sweep KEY=V1,V2 ...]
                                   refinement series (and sweeps of scene keys, e.g.
                                   parts.0.section.basis=linear,quadratic): CSV of errors and
                                   times per run, and error-vs-dofs / error-vs-time plots
  efg schema                       print the scene file reference (docs/scene.md)
  efg --help                       this text
  efg --version                    version and git revision

Options of run, check, mesh and study:
  --threads T                      threads per MPI rank (builds against an OpenMP Trilinos,
                                   docs/threads.md; default OMP_NUM_THREADS, else all cores)

Parallel: mpirun -np N efg run SCENE.yaml distributes the particles over N ranks; with threads,
  mpirun --bind-to none -np N efg run SCENE.yaml --threads T (N x T <= cores).

Exit codes:
  0  success
  1  any other failure (I/O error, internal error, unavailable feature)
  2  bad input: command line, scene file or mesh file (nothing is written)
  3  numerical failure (singular moment matrix, unstable time step, negative Jacobian, NaN,
     Newton divergence), reported with particle, step and time
  4  the run completed, but a reference value of the scene's verification block was missed
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
  if (first != "run" && first != "check" && first != "mesh" && first != "schema" &&
      first != "study")
    usage_error("unknown command '" + first +
                "'; expected run, check, mesh, study, schema, --help or --version");
  cl.command = first;
  std::vector<std::string> positional;
  for (std::size_t i = 1; i < args.size(); ++i) {
    const auto& a = args[i];
    if ((a == "--levels" || a == "--factor" || a == "--sweep") && cl.command == "study") {
      if (i + 1 >= args.size()) usage_error("option " + a + " needs a value");
      const auto& value = args[++i];
      try {
        if (a == "--levels") cl.levels = std::stoi(value);
        if (a == "--factor") cl.factor = std::stod(value);
      } catch (const std::exception&) {
        usage_error("option " + a + " expects a number, found '" + value + "'");
      }
      if (a == "--sweep") {
        if (value.find('=') == std::string::npos)
          usage_error("--sweep expects KEY=V1,V2,..., found '" + value + "'");
        cl.sweeps.push_back(value);
      }
      if (cl.levels < 1 || !(cl.factor > 1.0))
        usage_error("--levels must be >= 1 and --factor > 1");
    } else if (a == "--threads" || a.rfind("--threads=", 0) == 0) {
      if (cl.command == "schema")
        usage_error("option --threads belongs to run, check, mesh and study");
      const bool joined = a != "--threads";
      if (!joined && i + 1 >= args.size())
        usage_error("option --threads needs a number of threads per rank");
      const std::string value = joined ? a.substr(10) : args[++i];
      std::size_t used = 0;
      try {
        cl.threads = std::stoi(value, &used);
      } catch (const std::exception&) {
        used = 0;
      }
      if (used != value.size() || cl.threads < 1)
        usage_error("--threads expects a positive number of threads per rank, found '" + value +
                    "'");
    } else if (a == "-o" || a == "--output") {
      if (cl.command != "run" && cl.command != "study" && cl.command != "check")
        usage_error("option " + a + " belongs to 'efg run', 'efg check' and 'efg study'");
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
    const std::string what = cl.command == "schema"
                                 ? "no arguments"
                                 : (cl.command == "mesh" ? "SCENE.yaml OUT.exo" : "one SCENE.yaml");
    usage_error("'efg " + cl.command + "' expects " + what + ", got " +
                std::to_string(positional.size()) + " argument(s)");
  }
  if (expected >= 1) cl.scene = positional[0];
  if (expected == 2) cl.mesh_output = positional[1];
  if (cl.output_dir.empty()) cl.output_dir = ".";
  return cl;
}

}  // namespace efg
