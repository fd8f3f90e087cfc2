#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/Errors.hpp"
#include "model/ExactSolutions.hpp"
#include "scene/ExactSolutionNames.hpp"
#include "scene/ParameterListFromYaml.hpp"
#include "scene/SceneReader.hpp"
#include "scene/SceneSchema.hpp"
#include "scene/SchemaMarkdown.hpp"
#include "scene/UnreadPartKeys.hpp"

namespace efg {
namespace {

const char* kMinimal = R"(
mesh:
  generate: {element: quad4, lower: [0, 0], upper: [4, 1], cells: [8, 2]}
parts:
  - {name: strip, blocks: [block_1], material: m}
materials:
  - {name: m, model: linear_elastic, youngs_modulus: 100, poissons_ratio: 0.25}
boundary_conditions:
  - {name: clamp, type: displacement, node_set: xmin, x: 0, y: 0}
stages:
  - name: load
    driver: implicit
    end_time: 1
    linear_solver:
      Solver Type: GMRES
      Belos:
        Maximum Iterations: 200
        Convergence Tolerance: 1.0e-10
        Verbose: false
)";

TEST(SceneSchema, DocsAreGeneratedFromTheSchema) {
  std::ifstream in(std::string(EFG_SOURCE_DIR) + "/docs/scene.md");
  ASSERT_TRUE(in) << "docs/scene.md missing";
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_EQ(text.str(), schema::markdown(scene_schema(), "efg scene files"))
      << "docs/scene.md is out of date: regenerate with `build/efg schema > docs/scene.md`";
}

TEST(SceneSchema, DefaultsAreFilledIn) {
  const auto scene = parse_scene(kMinimal, "minimal.yaml");
  ASSERT_EQ(scene.parts.size(), 1u);
  const auto& s = scene.parts[0].section;
  EXPECT_EQ(s.basis, Basis::linear);
  EXPECT_EQ(s.kernel, KernelType::cubic_spline);
  EXPECT_EQ(s.integration, Integration::scni);
  EXPECT_EQ(s.dilation, std::vector<double>{1.5});
  EXPECT_EQ(scene.output.file, "minimal.e");
  EXPECT_EQ(scene.stages[0].settings["load_steps"].as<int>(), 1);
  EXPECT_EQ(scene.resolved["parts"][0]["section"]["spacing"].as<std::string>(), "cells");
  ASSERT_TRUE(scene.generator.has_value());
  EXPECT_EQ(scene.generator->dimension, 2);
  EXPECT_EQ(scene.generator->cells[0], 8);
}

TEST(SceneSchema, SolverSublistsBecomeTypedParameterLists) {
  const auto scene = parse_scene(kMinimal, "minimal.yaml");
  const auto list =
      parameter_list_from_yaml(scene.stages[0].settings["linear_solver"], "Linear Solver",
                               scene.file, "stages[0].linear_solver");
  EXPECT_EQ(list.get<std::string>("Solver Type"), "GMRES");
  const auto& belos = list.sublist("Belos");
  EXPECT_EQ(belos.get<int>("Maximum Iterations"), 200);
  EXPECT_DOUBLE_EQ(belos.get<double>("Convergence Tolerance"), 1e-10);
  EXPECT_FALSE(belos.get<bool>("Verbose"));
}

TEST(SceneSchema, EveryExampleSceneIsValid) {
  int count = 0;
  for (const auto& entry :
       std::filesystem::directory_iterator(std::string(EFG_SOURCE_DIR) + "/input")) {
    if (entry.path().extension() != ".yaml") continue;
    EXPECT_NO_THROW(parse_scene(read_scene_text(entry.path().string()), entry.path().string()))
        << entry.path();
    ++count;
  }
  EXPECT_GE(count, 1);
}

TEST(SceneSchema, MessagesCarryFileLineAndKeyPath) {
  std::string text = kMinimal;
  text.replace(text.find("poissons_ratio: 0.25"), 20, "poissons_ratio: 0.55");
  try {
    parse_scene(text, "bad.yaml");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              "bad.yaml:7:75: materials[0].poissons_ratio: expected a finite real in (-1, 0.5), "
              "found 0.55");
  }
}

}  // namespace
}  // namespace efg

// One registry: every exact solution the schema offers is implemented, and no other
// (wave_front used to be offered and then throw "no implementation").
TEST(SceneSchema, ExactSolutionChoicesAreImplemented) {
  auto offered = efg::exact_solution_names();
  auto implemented = efg::implemented_exact_solutions();
  std::sort(offered.begin(), offered.end());
  std::sort(implemented.begin(), implemented.end());
  EXPECT_EQ(offered, implemented);
}

namespace efg {
namespace {

// Each key is reported where its part's other choices leave it unread, and nowhere else.
TEST(UnreadPartKeys, WarnsOnlyOfKeysThePartsIntegrationLeavesUnread) {
  const auto warnings = [](const char* written, const char* integration) {
    YAML::Node resolved;
    resolved["section"]["integration"] = integration;
    return unread_part_keys("s.yaml", YAML::Load(written), resolved, "parts[0]");
  };
  const char* both = "{section: {gauss_order: 3, smoothing_quadrature: split}}";
  auto w = warnings(both, "gauss");
  ASSERT_EQ(w.size(), 1u);
  EXPECT_NE(w[0].find("s.yaml:1:50: parts[0].section.smoothing_quadrature: ignored"),
            std::string::npos)
      << w[0];
  w = warnings(both, "scni");
  ASSERT_EQ(w.size(), 1u);
  EXPECT_NE(w[0].find("s.yaml:1:25: parts[0].section.gauss_order: ignored"), std::string::npos)
      << w[0];
  EXPECT_EQ(warnings(both, "scni_subcells").size(), 1u);  // gauss_order
  EXPECT_EQ(warnings(both, "nodal").size(), 2u);
  EXPECT_TRUE(warnings("{section: {integration: gauss}}", "gauss").empty());
  EXPECT_TRUE(warnings("{name: p}", "scni").empty());
}

}  // namespace
}  // namespace efg
