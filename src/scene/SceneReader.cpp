#include "scene/SceneReader.hpp"

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "core/Errors.hpp"
#include "core/Log.hpp"
#include "scene/ContactInput.hpp"
#include "scene/DistributedReadChecks.hpp"
#include "scene/FieldInput.hpp"
#include "scene/InitialStateInput.hpp"
#include "scene/MeshInput.hpp"
#include "scene/PartFormulationCheck.hpp"
#include "scene/PlasticityInput.hpp"
#include "scene/RigidWallStages.hpp"
#include "scene/SceneAngles.hpp"
#include "scene/SceneNodeSets.hpp"
#include "scene/SceneSchema.hpp"
#include "scene/SchemaValidator.hpp"
#include "scene/StageLists.hpp"
#include "scene/UnreadPartKeys.hpp"
#include "scene/YamlDocument.hpp"

namespace efg {
namespace {

namespace fs = std::filesystem;

template <class T>
std::vector<T> as_vector(const YAML::Node& node) {
  std::vector<T> v;
  for (const auto& item : node) v.push_back(item.as<T>());
  return v;
}

std::string opt_string(const YAML::Node& node, const char* key) {
  return node[key] ? node[key].as<std::string>() : std::string();
}

template <class Enum>
Enum enum_of(const std::string& value, const std::vector<std::pair<const char*, Enum>>& table) {
  for (const auto& [name, e] : table)
    if (value == name) return e;
  throw std::logic_error("schema and enum table disagree on '" + value + "'");
}

class SceneBuilder {
 public:
  SceneBuilder(Scene& scene) : s_(scene) {}

  [[noreturn]] void fail(const YAML::Node& at, const std::string& path,
                         const std::string& message) const {
    throw InputError(schema::located_message(s_.file, at, path, message));
  }

  void build() {
    const auto& r = s_.resolved;
    const auto& d = s_.document;
    for (const auto& kv : r["parameters"])
      s_.parameters[kv.first.as<std::string>()] = kv.second.as<double>();
    s_.title = r["title"].as<std::string>();
    read_mesh_input(s_);
    for (std::size_t i = 0; i < r["materials"].size(); ++i)
      build_material(r["materials"][i], d["materials"][i], i);
    for (std::size_t i = 0; i < r["parts"].size(); ++i) build_part(r["parts"][i], d["parts"][i], i);
    for (std::size_t i = 0; i < r["curves"].size(); ++i)
      build_curve(r["curves"][i], d["curves"][i], i);
    for (std::size_t i = 0; i < r["boundary_conditions"].size(); ++i)
      build_bc(r["boundary_conditions"][i], d["boundary_conditions"][i], i);
    for (std::size_t i = 0; i < r["loads"].size(); ++i) build_load(r["loads"][i], d["loads"][i], i);
    for (std::size_t i = 0; i < r["initial_conditions"].size(); ++i) {
      const auto& ic = r["initial_conditions"][i];
      s_.initial_conditions.push_back({ic["type"].as<std::string>(),
                                       ic["node_set"].as<std::string>(),
                                       fields(ic["value"], d["initial_conditions"][i]["value"],
                                              "initial_conditions[" + std::to_string(i) + "].value",
                                              ExpressionVariables::position)});
    }
    for (const auto& p : r["probes"]) {
      ProbeSpec probe;
      probe.name = p["name"].as<std::string>();
      for (std::size_t k = 0; k < p["point"].size(); ++k)
        probe.point[k] = p["point"][k].as<double>();
      s_.probes.push_back(probe);
    }
    read_initial_state_input(s_);
    read_node_set_input(s_);
    read_angle_input(s_);
    std::vector<std::string> stage_names;
    for (const auto& st : r["stages"]) stage_names.push_back(st["name"].as<std::string>());
    check_stage_lists(s_, stage_names);
    for (std::size_t i = 0; i < r["stages"].size(); ++i)
      build_stage(r["stages"][i], d["stages"][i], i);
    check_plasticity_input(s_);
    read_contact_input(s_);
    s_.output.file = r["output"]["file"] ? r["output"]["file"].as<std::string>() : s_.name + ".e";
    s_.output.fields = as_vector<std::string>(r["output"]["fields"]);
    s_.output.history = opt_string(r["output"], "history");
    s_.output.history_node_sets = as_vector<std::string>(r["output"]["history_node_sets"]);
    s_.output.per_rank_files = opt_string(r["output"], "files") == "per_rank";
    check_output_files(d["output"]);
    check_part_formulations(s_);
    for (const auto& w : r["rigid_walls"])
      s_.rigid_walls.push_back({w["name"].as<std::string>(), as_vector<double>(w["point"]),
                                as_vector<double>(w["normal"]), opt_string(w, "node_set"),
                                w["penalty"].as<double>()});
    for (const auto& warning : check_rigid_wall_stages(s_)) Log::warning(warning);
    if (r["verification"]) {
      s_.verification = r["verification"];
      if (r["verification"]["exact_solution"])
        s_.exact_solution = r["verification"]["exact_solution"].as<std::string>();
      read_user_solution(s_, r["verification"], d["verification"]);
    }
    for (std::size_t i = 0; i < s_.boundary_conditions.size(); ++i) {
      const auto& bc = s_.boundary_conditions[i];
      if ((bc.from_exact[0] || bc.from_exact[1] || bc.from_exact[2]) && s_.exact_solution.empty())
        fail(d["boundary_conditions"][i]["from_exact_solution"],
             "boundary_conditions[" + std::to_string(i) + "].from_exact_solution",
             "needs verification.exact_solution, which the scene does not name");
    }
    check_nitsche_is_small_strain();
    for (std::size_t i = 0; i < s_.loads.size(); ++i)
      if (s_.loads[i].from_exact && s_.exact_solution.empty())
        fail(d["loads"][i]["from_exact_solution"],
             "loads[" + std::to_string(i) + "].from_exact_solution",
             "needs verification.exact_solution, which the scene does not name");
    check_distributed_read(s_);
  }

 private:
  void build_material(const YAML::Node& m, const YAML::Node& doc, std::size_t i) {
    MaterialSpec mat;
    mat.name = m["name"].as<std::string>();
    mat.model = m["model"].as<std::string>();
    if (m["density"]) mat.density = m["density"].as<double>();
    for (const auto& kv : m) {
      const auto key = kv.first.as<std::string>();
      if (key == "hardening_curve")
        mat.hardening_curve = kv.second.as<std::string>();
      else if (key == "yield_curve")
        mat.yield_curve = kv.second.as<std::string>();
      else if (key == "loading_curve")
        mat.loading_curve = kv.second.as<std::string>();
      else if (double number = 0;
               key == "youngs_modulus" && !YAML::convert<double>::decode(kv.second, number)) {
        // an expression of x, y, z (validated): a graded material
        mat.youngs_modulus_field =
            field(kv.second, doc[key], "materials[" + std::to_string(i) + "]." + key,
                  ExpressionVariables::position);
        mat.constants[key] = 0.0;  // the reference, set by build_model from the mesh
      } else if (key != "name" && key != "model" && key != "density")
        mat.constants[key] = kv.second.as<double>();
    }
    // No coupling between the principal directions: Poisson's ratio 0, which the elastic
    // fall-backs and the contact's bulk modulus read (contact/PenaltyContact.cpp).
    if (mat.model == "low_density_foam") mat.constants["poissons_ratio"] = 0.0;
    s_.materials.push_back(mat);
  }

  void build_part(const YAML::Node& p, const YAML::Node& doc, std::size_t i) {
    const std::string path = "parts[" + std::to_string(i) + "]";
    for (const auto& message : unread_part_keys(s_.file, doc, p, path)) Log::warning(message);
    PartSpec part;
    part.name = p["name"].as<std::string>();
    part.blocks = as_vector<std::string>(p["blocks"]);
    part.material = p["material"].as<std::string>();
    part.thickness = p["thickness"].as<double>();
    part.plane_stress = p["plane"].as<std::string>() == "stress";
    if (p["formulation"].as<std::string>() == "mixed_up")
      part.formulation = PartFormulation::mixed_up;
    if (p["pressure_cells"].as<std::string>() == "patch")
      part.pressure_cells = PressureCellChoice::patch;
    if (const auto& sh = p["shell"]; sh) {
      part.shell = ShellSpec{std::nullopt,
                             sh["thickness_points"].as<int>(),
                             sh["shear_stabilization"].as<double>(),
                             {}};
      if (sh["thickness"])
        part.shell->thickness = field(sh["thickness"], doc["shell"]["thickness"],
                                      path + ".shell.thickness", ExpressionVariables::position);
      if (const auto& r = sh["reference"]; r)
        for (const char* axis : {"x", "y", "z"})
          part.shell->reference.push_back(field(r[axis], doc["shell"]["reference"][axis],
                                                path + ".shell.reference." + axis,
                                                ExpressionVariables::position));
    }
    const auto* material = s_.find_material(part.material);
    if (!material) {
      std::string names;
      for (const auto& m : s_.materials) names += (names.empty() ? "" : ", ") + m.name;
      fail(doc["material"], path + ".material",
           "no material named '" + part.material + "'; materials: " + names);
    }
    const auto& sec = p["section"];
    auto& out = part.section;
    out.basis = enum_of<Basis>(sec["basis"].as<std::string>(),
                               {{"linear", Basis::linear}, {"quadratic", Basis::quadratic}});
    out.kernel = enum_of<KernelType>(sec["kernel"].as<std::string>(),
                                     {{"cubic_spline", KernelType::cubic_spline},
                                      {"quadratic_spline", KernelType::quadratic_spline},
                                      {"quartic_spline", KernelType::quartic_spline}});
    out.support =
        enum_of<SupportShape>(sec["support"].as<std::string>(),
                              {{"box", SupportShape::box}, {"sphere", SupportShape::sphere}});
    out.dilation = as_vector<double>(sec["dilation"]);
    out.spacing = enum_of<SpacingMeasure>(sec["spacing"].as<std::string>(),
                                          {{"cells", SpacingMeasure::cells},
                                           {"edges", SpacingMeasure::edges},
                                           {"neighbors", SpacingMeasure::neighbors}});
    out.per_part_support = sec["support_size"].as<std::string>() == "per_part";
    out.integration = enum_of<Integration>(sec["integration"].as<std::string>(),
                                           {{"scni", Integration::scni},
                                            {"scni_subcells", Integration::scni_subcells},
                                            {"nodal", Integration::nodal},
                                            {"gauss", Integration::gauss}});
    out.smoothing_quadrature =
        enum_of<SmoothingQuadrature>(sec["smoothing_quadrature"].as<std::string>(),
                                     {{"auto", SmoothingQuadrature::automatic},
                                      {"split", SmoothingQuadrature::split},
                                      {"centroid", SmoothingQuadrature::centroid}});
    out.gauss_order = sec["gauss_order"].as<int>();
    out.formulation = enum_of<Formulation>(sec["formulation"].as<std::string>(),
                                           {{"small_strain", Formulation::small_strain},
                                            {"total_lagrangian", Formulation::total_lagrangian}});
    if (out.support == SupportShape::sphere && out.dilation.size() > 1)
      fail(doc["section"]["dilation"], path + ".section.dilation",
           "a sphere support takes one dilation value, found " +
               std::to_string(out.dilation.size()));
    // (a shell's linear section law in Green-Lagrange strains is the usual small-strain,
    // large-rotation shell: docs/shells.md "Finite rotations")
    if (material->model == "linear_elastic" && out.formulation != Formulation::small_strain &&
        !doc["shell"]) {
      const YAML::Node at = doc["section"] && doc["section"]["formulation"]
                                ? doc["section"]["formulation"]
                                : doc["material"];
      fail(at, path + ".section.formulation",
           "material '" + material->name +
               "' (model linear_elastic) is a small-strain model: expected formulation "
               "small_strain, found " +
               sec["formulation"].as<std::string>());
    }
    if ((material->model == "neo_hookean" || material->model == "crushable_foam" ||
         material->model == "low_density_foam") &&
        out.formulation != Formulation::total_lagrangian) {
      const YAML::Node at = doc["section"] && doc["section"]["formulation"]
                                ? doc["section"]["formulation"]
                                : doc["material"];
      fail(at, path + ".section.formulation",
           "material '" + material->name + "' (model " + material->model +
               ") is a finite-strain model: expected formulation "
               "total_lagrangian, found " +
               sec["formulation"].as<std::string>());
    }
    s_.parts.push_back(part);
  }

  void build_curve(const YAML::Node& c, const YAML::Node& doc, std::size_t i) {
    const std::string path = "curves[" + std::to_string(i) + "]";
    CurveSpec curve{c["name"].as<std::string>(), as_vector<double>(c["time"]),
                    as_vector<double>(c["value"])};
    if (curve.time.size() != curve.value.size())
      fail(doc["value"], path + ".value",
           "expected as many values as times (" + std::to_string(curve.time.size()) + "), found " +
               std::to_string(curve.value.size()));
    for (std::size_t k = 1; k < curve.time.size(); ++k)
      if (!(curve.time[k] > curve.time[k - 1]))
        fail(doc["time"][k], path + ".time[" + std::to_string(k) + "]",
             "expected strictly increasing times, found " + doc["time"][k].Scalar() + " after " +
                 doc["time"][k - 1].Scalar());
    s_.curves.push_back(curve);
  }

  void require_curve(const YAML::Node& doc, const std::string& path,
                     const std::string& name) const {
    if (name.empty()) return;
    for (const auto& c : s_.curves)
      if (c.name == name) return;
    fail(doc["curve"], path + ".curve", "no curve named '" + name + "' in curves");
  }

  void build_bc(const YAML::Node& b, const YAML::Node& doc, std::size_t i) {
    const std::string path = "boundary_conditions[" + std::to_string(i) + "]";
    BoundaryConditionSpec bc;
    bc.name = b["name"].as<std::string>();
    bc.type = b["type"].as<std::string>();
    bc.node_set = b["node_set"].as<std::string>();
    bc.method = b["method"].as<std::string>();
    if (b["penalty"]) bc.penalty = b["penalty"].as<double>();
    const char* axes[3] = {"x", "y", "z"};
    for (std::size_t c = 0; c < 3; ++c)
      if (b[axes[c]])
        bc.components[c] = field(b[axes[c]], doc[axes[c]], path + "." + axes[c],
                                 ExpressionVariables::position_and_time);
    const char* rotations[2] = {"rx", "ry"};
    for (std::size_t c = 0; c < 2; ++c)
      if (b[rotations[c]])
        bc.rotations[c] = field(b[rotations[c]], doc[rotations[c]], path + "." + rotations[c],
                                ExpressionVariables::position_and_time);
    if (b["from_exact_solution"])
      for (const auto& c : b["from_exact_solution"]) {
        const auto axis = static_cast<std::size_t>(c.as<std::string>()[0] - 'x');
        if (bc.components[axis])
          fail(doc["from_exact_solution"], path + ".from_exact_solution",
               "component " + c.as<std::string>() +
                   " is also given a value; give it one or the other");
        bc.from_exact[axis] = true;
      }
    bc.curve = opt_string(b, "curve");
    require_curve(doc, path, bc.curve);
    bc.stages.names = as_vector<std::string>(b["stages"]);
    s_.boundary_conditions.push_back(bc);
  }

  void build_load(const YAML::Node& l, const YAML::Node& doc, std::size_t i) {
    const std::string path = "loads[" + std::to_string(i) + "]";
    LoadSpec load;
    load.name = l["name"].as<std::string>();
    load.type = l["type"].as<std::string>();
    load.set = l["side_set"] ? l["side_set"].as<std::string>() : opt_string(l, "node_set");
    if (l["parts"]) load.parts = as_vector<std::string>(l["parts"]);
    const auto varying = load.type == "nodal_force" ? ExpressionVariables::none
                                                    : ExpressionVariables::position_and_time;
    if (l["value"])
      load.value =
          l["value"].IsSequence()
              ? fields(l["value"], doc["value"], path + ".value", varying)
              : std::vector<ScalarField>{field(l["value"], doc["value"], path + ".value", varying)};
    load.from_exact = l["from_exact_solution"] && l["from_exact_solution"].as<bool>();
    load.follower = l["follower"] && l["follower"].as<bool>();
    if (l["point"])
      for (std::size_t k = 0; k < l["point"].size() && k < 3; ++k)
        load.point[k] = l["point"][k].as<double>();
    if ((load.type == "traction" || load.type == "body_force") &&
        load.from_exact == !load.value.empty())
      fail(doc, path, "expected exactly one of value, from_exact_solution: true");
    load.curve = opt_string(l, "curve");
    require_curve(doc, path, load.curve);
    load.stages.names = as_vector<std::string>(l["stages"]);
    for (std::size_t k = 0; k < load.parts.size(); ++k) {
      bool found = false;
      for (const auto& p : s_.parts) found = found || p.name == load.parts[k];
      if (!found)
        fail(doc["parts"][k], path + ".parts[" + std::to_string(k) + "]",
             "no part named '" + load.parts[k] + "'");
    }
    s_.loads.push_back(load);
  }

  ScalarField field(const YAML::Node& resolved, const YAML::Node& doc, const std::string& path,
                    ExpressionVariables variables) const {
    return read_field(s_, resolved, doc, path, variables);
  }
  std::vector<ScalarField> fields(const YAML::Node& resolved, const YAML::Node& doc,
                                  const std::string& path, ExpressionVariables variables) const {
    return read_fields(s_, resolved, doc, path, variables);
  }

  void build_stage(const YAML::Node& st, const YAML::Node& doc, std::size_t i) {
    StageSpec stage;
    stage.name = st["name"].as<std::string>();
    stage.driver = st["driver"].as<std::string>();
    stage.end_time = st["end_time"].as<double>();
    if (st["output_interval"]) stage.output_interval = st["output_interval"].as<double>();
    stage.settings = st;
    const std::string path = "stages[" + std::to_string(i) + "]";
    if (!s_.stages.empty() && !(stage.end_time > s_.stages.back().end_time))
      fail(doc["end_time"], path + ".end_time",
           "expected an end time after the previous stage's (" +
               std::to_string(s_.stages.back().end_time) + "), found " + st["end_time"].Scalar() +
               "; stages run one after another on one time axis");
    if (stage.driver == "implicit") {
      check_linear_solver(st, doc, i);
      for (std::size_t b = 0; b < s_.boundary_conditions.size(); ++b)
        if (s_.boundary_conditions[b].type == "velocity" &&
            s_.boundary_conditions[b].stages.includes(stage.name))
          fail(d_bc(b), "boundary_conditions[" + std::to_string(b) + "].type",
               "a velocity condition, but stage '" + stage.name +
                   "' is implicit (static), where velocities do not exist; expected type: "
                   "displacement (with a curve for a motion over time), or stages: naming the "
                   "explicit stages it acts in");
      bool held = false;
      for (const auto& bc : s_.boundary_conditions)
        held = held || (bc.type == "displacement" && bc.stages.includes(stage.name));
      if (!held)
        fail(doc["driver"], "stages[" + std::to_string(i) + "].driver",
             "an implicit (static) stage needs displacement conditions that hold the body "
             "against rigid-body motion; the scene has none, so the body is free and its "
             "stiffness singular (add boundary_conditions, or use driver: explicit)");
    }
    if (stage.driver == "explicit")
      for (std::size_t p = 0; p < s_.parts.size(); ++p)
        if (!s_.find_material(s_.parts[p].material)->density)
          fail(doc["driver"], "stages[" + std::to_string(i) + "].driver",
               "an explicit stage needs a density for every material; material '" +
                   s_.parts[p].material + "' has none");
    s_.stages.push_back(stage);
  }

  // Output files live inside the output folder (-o): a relative file path that names a file and
  // does not climb out of it. The history CSV sits beside the results and is another file.
  void check_output_file(const YAML::Node& at, const std::string& path,
                         const std::string& given) const {
    const fs::path p(given);
    const auto normal = p.lexically_normal();
    std::string why;
    if (given.empty())
      why = "an empty file name";
    else if (given.back() == '/' || !p.has_filename() || p.filename() == "." ||
             p.filename() == "..")
      why = "'" + given + "' names a folder";
    else if (p.is_absolute())
      why = "'" + given + "' is an absolute path";
    else if (!normal.empty() && *normal.begin() == "..")
      why = "'" + given + "' leaves the output folder";
    if (!why.empty())
      fail(at, path,
           "expected a file name relative to the output folder (-o), such as results.e; found " +
               why);
  }

  void check_output_files(const YAML::Node& doc) const {
    const YAML::Node none;
    check_output_file(doc && doc["file"] ? doc["file"] : none, "output.file", s_.output.file);
    if (s_.output.history.empty() && !(doc && doc["history"])) return;
    const YAML::Node at = doc["history"];
    check_output_file(at, "output.history", s_.output.history);
    const auto results = fs::path(s_.output.file).lexically_normal();
    const auto history = (results.parent_path() / s_.output.history).lexically_normal();
    if (history == results)
      fail(at, "output.history",
           "'" + s_.output.history +
               "' is also output.file; expected a different file name "
               "for the history CSV (for example " +
               s_.name + ".csv)");
  }

  // The static part of the linear solver choice (solvers/LinearSolverPlan.cpp resolves the rest
  // with the model's size): caught here so that `check` reports it and nothing is written.
  void check_linear_solver(const YAML::Node& st, const YAML::Node& doc, std::size_t i) const {
    const std::string at = "stages[" + std::to_string(i) + "].preconditioner";
    const YAML::Node prec = st["preconditioner"];
    if (!prec || !prec.IsMap()) return;
    const YAML::Node written = doc["preconditioner"];
    if (prec["Type"]) {
      const auto type = prec["Type"].as<std::string>();
      if (type != "direct" && type != "MueLu" && type != "auxiliary" && type != "Ifpack2" &&
          type != "None")
        fail(written["Type"], at + ".Type",
             "expected one of direct, MueLu, auxiliary, Ifpack2, None; found '" + type + "'");
      if (st["solver"].as<std::string>() == "direct" && type != "direct")
        fail(written["Type"], at + ".Type",
             "'" + type + "' contradicts solver: direct (remove one of them)");
    }
    const auto direct = prec["solver"] ? prec["solver"].as<std::string>() : "MUMPS";
    if (direct != "MUMPS" && direct != "UMFPACK" && direct != "KLU2")
      fail(written["solver"], at + ".solver",
           "expected MUMPS (the default), UMFPACK or KLU2 (Amesos2; Tacho crashed in this "
           "Trilinos build), found '" +
               prec["solver"].as<std::string>() + "'");
  }

  // Nitsche's consistency terms use the stress on the boundary; their tangent here omits the
  // derivative of the material tangent (docs/boundary_conditions.md), exact for small strain
  // only: a finite-strain part would lose Newton's quadratic convergence, so it is refused when
  // an implicit stage would solve it (explicit stages need no tangent: drivers/WeakSupports).
  void check_nitsche_is_small_strain() const {
    bool implicit = false;
    for (const auto& st : s_.stages) implicit = implicit || st.driver == "implicit";
    if (!implicit) return;
    const PartSpec* finite = nullptr;
    for (const auto& p : s_.parts)
      if (p.section.formulation == Formulation::total_lagrangian) finite = &p;
    if (!finite) return;
    for (std::size_t b = 0; b < s_.boundary_conditions.size(); ++b)
      if (s_.boundary_conditions[b].method == "nitsche") {
        const YAML::Node bc = s_.document["boundary_conditions"][b];
        fail(bc["method"] ? bc["method"] : bc,
             "boundary_conditions[" + std::to_string(b) + "].method",
             "method nitsche is available for small-strain parts only (its tangent lacks the "
             "finite-strain term), but part '" +
                 finite->name + "' is total_lagrangian; expected method penalty or transformation");
      }
  }

  YAML::Node d_bc(std::size_t b) const {
    const YAML::Node bc = s_.document["boundary_conditions"][b];
    return bc["type"] ? bc["type"] : bc;
  }

  Scene& s_;
};

}  // namespace

std::string read_scene_text(const std::string& file) {
  std::ifstream in(file);
  if (!in)
    throw InputError(file +
                     ": cannot read the scene file (expected an existing, readable YAML file)");
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

Scene parse_scene(const std::string& text, const std::string& file) {
  Scene scene;
  scene.file = file;
  const fs::path p(file);
  scene.directory = p.has_parent_path() ? p.parent_path().string() : ".";
  scene.name = p.stem().string();
  scene.document = load_single_document(text, file);
  if (!scene.document.IsMap())
    throw InputError(
        file + ": expected a YAML map of scene sections (mesh, parts, materials, ...), found " +
        (scene.document.IsNull() ? std::string("an empty document")
                                 : std::string("something else")));
  scene.resolved = schema::validate(scene.document, scene_schema(), file);
  SceneBuilder(scene).build();
  return scene;
}

}  // namespace efg
