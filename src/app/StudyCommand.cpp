// efg study: a refinement series of a scene (cells of a generated mesh multiplied by factor^level),
// optionally swept over scene keys, each run in this process; one CSV row per run with its
// errors and phase times, then plots by scripts/plot_study.py (matplotlib from Debian).
#include <yaml-cpp/yaml.h>
#include <Teuchos_TimeMonitor.hpp>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <sstream>

#include "app/Commands.hpp"
#include "core/Errors.hpp"
#include "core/Log.hpp"
#include "core/Version.hpp"
#include "mesh/MeshGenerator.hpp"
#include "parallel/RootBroadcast.hpp"
#include "run/RunReport.hpp"
#include "run/Simulation.hpp"
#include "scene/SceneReader.hpp"

namespace efg {
namespace {

struct Sweep {
  std::string key;
  std::vector<std::string> values;
};

std::vector<Sweep> parse_sweeps(const std::vector<std::string>& args) {
  std::vector<Sweep> sweeps;
  for (const auto& a : args) {
    Sweep s;
    s.key = a.substr(0, a.find('='));
    std::stringstream values(a.substr(a.find('=') + 1));
    for (std::string v; std::getline(values, v, ',');) s.values.push_back(v);
    sweeps.push_back(s);
  }
  return sweeps;
}

// The node at a dotted key path ("parts.0.section.basis"), created when missing.
YAML::Node node_at(YAML::Node root, const std::string& key, const std::string& file) {
  std::stringstream path(key);
  YAML::Node node = root;
  std::vector<std::string> parts;
  for (std::string p; std::getline(path, p, '.');) parts.push_back(p);
  for (std::size_t i = 0; i < parts.size(); ++i) {
    const auto& p = parts[i];
    YAML::Node next;
    if (node.IsSequence()) {
      const auto index = static_cast<std::size_t>(std::atoi(p.c_str()));
      if (index >= node.size())
        throw InputError("command line: --sweep " + key + ": " + file + " has no entry " + p);
      next = node[index];
    } else {
      if (!node[p]) node[p] = YAML::Node(YAML::NodeType::Map);
      next = node[p];
    }
    node.reset(next);
  }
  return node;
}

// The study table's header: the swept keys, the level, errors, and one column per report phase.
void write_study_header(std::ostream& csv, const std::vector<Sweep>& sweeps) {
  for (const auto& s : sweeps) csv << s.key << ",";
  csv << "level,h,dofs,l2_rel_error,energy_rel_error,max_nodal_error,pressure_rel_error";
  for (const auto& phase : report_phases()) {
    std::string column = phase;
    for (auto& c : column)
      if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
    csv << "," << column << "_seconds";
  }
  csv << ",total_seconds\n";
}

// Cartesian product of the sweeps (one empty combination without sweeps).
std::vector<std::vector<std::string>> combinations(const std::vector<Sweep>& sweeps) {
  std::vector<std::vector<std::string>> combos(1);
  for (const auto& s : sweeps) {
    std::vector<std::vector<std::string>> next;
    for (const auto& c : combos)
      for (const auto& v : s.values) {
        auto e = c;
        e.push_back(v);
        next.push_back(e);
      }
    combos = next;
  }
  return combos;
}

// The scene text of one run: the sweep values set, the generated mesh refined by factor^level;
// `h` receives the largest cell size.
// The mesh sizes come from the validated base scene (they may be expressions of parameters);
// with a coordinate map, h is the cell size of the box before the map (its ratios between levels,
// all the rate fits use, are those of the mapped mesh).
std::string level_scene(const std::string& text, const GeneratorSpec& base,
                        const std::vector<Sweep>& sweeps, const std::vector<std::string>& combo,
                        const CommandLine& cl, int level, double& h) {
  YAML::Node doc = YAML::Load(text);
  for (std::size_t i = 0; i < sweeps.size(); ++i)
    node_at(doc, sweeps[i].key, cl.scene) = YAML::Load(combo[i]);
  const double scale = std::pow(cl.factor, level);
  auto cells = doc["mesh"]["generate"]["cells"];
  h = 0;
  for (std::size_t d = 0; d < cells.size(); ++d) {
    const int n = static_cast<int>(std::lround(base.cells[d] * scale));
    cells[d] = n;
    h = std::max(h, (base.upper[d] - base.lower[d]) / n);
  }
  YAML::Emitter out;
  out << doc;
  return out.c_str();
}

// Nodes of the generated mesh at `level` (a double: it may overflow any integer).
double level_nodes(const GeneratorSpec& base, double factor, int level) {
  double nodes = 1;
  for (int d = 0; d < base.dimension; ++d)
    nodes *= std::round(base.cells[static_cast<std::size_t>(d)] * std::pow(factor, level)) + 1;
  return nodes;
}

// The finest level must be a mesh the generator can hold: refused before anything runs (an
// absurd --levels used to start the series and fail, or overflow the cell counts, much later).
void check_levels(const GeneratorSpec& base, const CommandLine& cl) {
  if (level_nodes(base, cl.factor, cl.levels - 1) <= kMaxGeneratedNodes) return;
  int most = 0;
  while (level_nodes(base, cl.factor, most) <= kMaxGeneratedNodes) ++most;
  std::ostringstream o;
  o << "command line: --levels " << cl.levels << ": level " << cl.levels - 1
    << " would refine the mesh.generate.cells of " << cl.scene << " by " << cl.factor << "^"
    << cl.levels - 1 << ", beyond the " << kMaxGeneratedNodes
    << " nodes a generated mesh may have; expected at most " << most << " levels with --factor "
    << cl.factor;
  throw InputError(o.str());
}

// The message of an error found in the scene with the sweep values, without the scene's
// file:line:col (the lines are those of the re-emitted text, not of the file).
std::string without_location(const std::string& message, const std::string& file) {
  if (message.rfind(file, 0) != 0) return message;
  std::size_t at = file.size();
  while (at < message.size() &&
         (message[at] == ':' || std::isdigit(static_cast<unsigned char>(message[at]))))
    ++at;
  while (at < message.size() && message[at] == ' ') ++at;
  return message.substr(at);
}

// Every run's scene (each combination of sweep values at each level) validated before anything
// runs or is written: a bad sweep value used to fail after the earlier runs had written their
// results, at a line of the scene that does not hold it.
void check_study_scenes(const std::string& text, const GeneratorSpec& base,
                        const std::vector<Sweep>& sweeps, const CommandLine& cl) {
  for (const auto& combo : combinations(sweeps))
    for (int level = 0; level < cl.levels; ++level) {
      double h = 0;
      try {
        parse_scene(level_scene(text, base, sweeps, combo, cl, level, h), cl.scene);
      } catch (const InputError& e) {
        std::string values;
        for (std::size_t i = 0; i < sweeps.size(); ++i)
          values += (i ? ", " : "") + sweeps[i].key + "=" + combo[i];
        throw InputError("command line: --sweep " + values + ": " + cl.scene +
                         (sweeps.size() > 1 ? " with these values" : " with this value") +
                         " is not a valid scene (level " + std::to_string(level) +
                         "): " + without_location(e.what(), cl.scene) + "; nothing was run");
      }
    }
}

}  // namespace

void study_command(const CommPtr& comm, const CommandLine& cl) {
  const auto bytes = produce_on_root(comm, [&] {
    const auto t = read_scene_text(cl.scene);
    return std::vector<char>(t.begin(), t.end());
  });
  const std::string text(bytes.begin(), bytes.end());
  const auto base = parse_scene(text, cl.scene);  // validates before anything runs
  if (!base.generator)
    throw InputError(cl.scene +
                     ": mesh: a study refines a generated mesh (mesh.generate), not a mesh file");
  const auto sweeps = parse_sweeps(cl.sweeps);
  check_levels(*base.generator, cl);
  check_study_scenes(text, *base.generator, sweeps, cl);
  const std::filesystem::path dir(cl.output_dir);
  if (comm->getRank() == 0) std::filesystem::create_directories(dir);
  const auto csv_path = (dir / (base.name + "_study.csv")).string();
  std::ofstream csv;
  if (comm->getRank() == 0) {
    csv.open(csv_path);
    write_study_header(csv, sweeps);
  }
  for (const auto& combo : combinations(sweeps))
    for (int level = 0; level < cl.levels; ++level) {
      double h = 0;
      const auto scene_text = level_scene(text, *base.generator, sweeps, combo, cl, level, h);
      std::string label = base.name;
      for (const auto& v : combo) label += "_" + v;
      label += "_L" + std::to_string(level);
      Log::info("study run " + label);
      Teuchos::TimeMonitor::zeroOutTimers();
      const auto started = std::chrono::steady_clock::now();
      const Model model = build_model(comm, parse_scene(scene_text, cl.scene));
      const double setup =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
      const auto path = (dir / (label + ".e")).string();
      const auto outcome = run_stages(comm, model, path, setup);
      const double total =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
      if (comm->getRank() != 0) continue;
      for (const auto& v : combo) csv << v << ",";
      csv << std::setprecision(10) << level << "," << h << ","
          << model.maps.owned_dofs->getGlobalNumElements();
      if (outcome.errors) {
        csv << "," << outcome.errors->l2_relative << "," << outcome.errors->energy_relative << ","
            << outcome.errors->max_nodal << ",";
        if (outcome.errors->pressure_relative >= 0) csv << outcome.errors->pressure_relative;
      } else {
        csv << ",,,,";
      }
      for (const auto& phase : report_phases()) {
        const auto timer = Teuchos::TimeMonitor::lookupCounter("efg: " + phase);
        csv << "," << (timer.is_null() ? 0.0 : timer->totalElapsedTime());
      }
      csv << "," << total << "\n" << std::flush;
    }
  if (comm->getRank() != 0) return;
  csv.close();
  Log::info("study table: " + csv_path);
  const std::string plot = std::string("/usr/bin/python3 '") + scripts_directory +
                           "/plot_study.py' '" + csv_path + "' '" + (dir / base.name).string() +
                           "'";
  if (std::system(plot.c_str()) != 0) throw std::runtime_error("plotting failed: " + plot);
  Log::info("study plots: " + (dir / (base.name + "_error_vs_dofs.png")).string() + ", " +
            (dir / (base.name + "_error_vs_time.png")).string());
}

}  // namespace efg
