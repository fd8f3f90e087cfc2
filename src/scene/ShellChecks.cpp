#include "scene/ShellChecks.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <set>
#include <sstream>

#include "core/Errors.hpp"
#include "scene/SchemaValidator.hpp"
#include "scene/ShellReferenceMap.hpp"

namespace efg {
namespace {

[[noreturn]] void fail(const Scene& s, const YAML::Node& at, const std::string& path,
                       const std::string& message) {
  throw InputError(schema::located_message(s.file, at, path, message));
}

// A curved reference must be a regular map of the flat mesh (docs/shells.md, "Curved
// references"): at every node of the part's blocks the tangents dX/dx and dX/dy (central
// differences of step 1e-6 of the mesh's size) span a plane, |dX/dx x dX/dy| above 1e-6 of
// |dX/dx| |dX/dy|, and neither vanishes. An isometry (the unrolled developable surface) keeps the
// flat mesh's spacing on the surface; other maps (a sphere over latitude and longitude) stretch
// it, which the strains' metric accounts for (shells/ShellMetric.hpp).
void check_regular_map(const Scene& s, const BackgroundMesh& mesh, const PartSpec& part,
                       const YAML::Node& at, const std::string& path) {
  const auto& map = part.shell->reference;
  const double h = shell_map_step(mesh);
  for (const auto& block : mesh.blocks) {
    if (std::find(part.blocks.begin(), part.blocks.end(), block.name) == part.blocks.end())
      continue;
    for (auto node : block.connectivity) {
      const double* xy = mesh.coordinates.data() + 2 * static_cast<std::size_t>(node);
      const auto point = shell_map_point(map, xy, h);
      const auto &t1 = point.tangent[0], &t2 = point.tangent[1];
      const double l1 = std::sqrt(t1[0] * t1[0] + t1[1] * t1[1] + t1[2] * t1[2]),
                   l2 = std::sqrt(t2[0] * t2[0] + t2[1] * t2[1] + t2[2] * t2[2]);
      const std::array<double, 3> n = {t1[1] * t2[2] - t1[2] * t2[1], t1[2] * t2[0] - t1[0] * t2[2],
                                       t1[0] * t2[1] - t1[1] * t2[0]};
      const double area = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
      if (std::isfinite(area) && l1 > 1e-6 && l2 > 1e-6 && area > 1e-6 * l1 * l2) continue;
      std::ostringstream o;
      o.precision(9);
      o << "the reference map is singular at (x, y) = (" << xy[0] << ", " << xy[1]
        << "): |dX/dx| = " << l1 << ", |dX/dy| = " << l2 << ", |dX/dx x dX/dy| = " << area
        << "; expected a regular map (independent tangents: the surface over the mesh without "
           "folds or collapsed edges, e.g. no pole)";
      fail(s, at, path, o.str());
    }
  }
}

// Solid scenes: the shell-only keys have nothing to act on.
void check_solid_scene(const Scene& s) {
  const auto& d = s.document;
  for (std::size_t i = 0; i < s.boundary_conditions.size(); ++i)
    for (std::size_t c = 0; c < 2; ++c)
      if (s.boundary_conditions[i].rotations[c]) {
        const char* key = c == 0 ? "rx" : "ry";
        fail(s, d["boundary_conditions"][i][key],
             "boundary_conditions[" + std::to_string(i) + "]." + key,
             "a rotation is a shell dof, and no part of this scene is a shell (parts[].shell); "
             "expected x, y or z");
      }
  for (std::size_t i = 0; i < s.output.fields.size(); ++i)
    if (s.output.fields[i] == "resultants" || s.output.fields[i] == "thickness")
      fail(s, d["output"]["fields"][i], "output.fields[" + std::to_string(i) + "]",
           s.output.fields[i] +
               " (of a section: forces and moments per unit length, its thickness) is a shell "
               "field, and no part of this scene is a shell; expected stress or strain");
  for (std::size_t i = 0; i < s.loads.size(); ++i)
    if (s.loads[i].type == "shell_pressure" || s.loads[i].type == "shell_edge_load" ||
        s.loads[i].type == "shell_point_load")
      fail(s, d["loads"][i]["type"], "loads[" + std::to_string(i) + "].type",
           s.loads[i].type +
               " loads shell parts, and no part of this scene is a shell; expected pressure, "
               "traction (on a side set), nodal_force or body_force");
}

// Rigid bodies and contacts with shells (contact/ShellRigidContact.hpp): explicit stages,
// contacts of shell parts with a rigid body.
void check_shell_contacts(const Scene& s) {
  const auto& d = s.document;
  for (std::size_t i = 0; i < s.contacts.size(); ++i) {
    const auto& c = s.contacts[i];
    const auto path = "contacts[" + std::to_string(i) + "]";
    if (c.rigid_body.empty())
      fail(s, d["contacts"][i], path,
           "shells touch rigid bodies in this version, not other parts: expected rigid_body");
    for (const auto& stage : s.stages)
      if (c.stages.includes(stage.name) && stage.driver != "explicit")
        fail(s, d["contacts"][i], path,
             "shell contact acts in explicit stages in this version, but stage '" + stage.name +
                 "' is implicit: expected the contact's stages to name explicit ones");
  }
}

}  // namespace

void check_shell_scene(const Scene& s, const BackgroundMesh& mesh) {
  if (!s.has_shells()) return check_solid_scene(s);
  const auto& d = s.document;
  for (std::size_t i = 0; i < s.parts.size(); ++i) {
    const auto& part = s.parts[i];
    const auto path = "parts[" + std::to_string(i) + "]";
    const auto& pd = d["parts"][i];
    if (!part.shell)
      fail(s, pd, path,
           "a solid part beside shell parts: coupling solids and shells is not built yet; make "
           "every part a shell (parts[].shell) or none");
    if (mesh.dimension != 2)
      fail(s, pd["shell"], path + ".shell",
           "shells need a mesh of their mid-surface: 2D, or a surface in 3D (SHELL4, TRISHELL3, "
           "QUAD4 or TRI3 cells only); this mesh is " +
               std::to_string(mesh.dimension) + "D with solid cells");
    if (!mesh.surface.empty() && !part.shell->reference.empty())
      fail(s, pd["shell"]["reference"], path + ".shell.reference",
           "the mesh is a shell surface in 3D already (its nodes are the reference): a "
           "reference map is for 2D meshes; expected no reference");
    if (!mesh.surface.empty() && part.section.formulation != Formulation::total_lagrangian)
      fail(s, pd["section"], path + ".section",
           "a shell surface read in 3D is a curved reference, a finite-rotation shell: expected "
           "section.formulation: total_lagrangian (a small load step gives the linear response)");
    const auto& material = *s.find_material(part.material);
    if (material.model != "linear_elastic" && material.model != "j2_plasticity")
      fail(s, pd["material"], path + ".material",
           "shells take a linear_elastic or j2_plasticity material in this version, not " +
               material.model);
    if (material.model == "j2_plasticity") {
      if (material.constants.count("failure_strain"))
        fail(s, d["materials"], "materials",
             "material '" + material.name + "' of shell part '" + part.name +
                 "' has a failure_strain: erosion of shells is not built yet");
    }
    if (part.section.integration == Integration::gauss ||
        part.section.integration == Integration::scni_subcells)
      fail(s, pd["section"]["integration"], path + ".section.integration",
           "shells are integrated at the particles: expected scni or nodal");
    if (part.section.formulation != s.parts.front().section.formulation)
      fail(s, pd["section"]["formulation"], path + ".section.formulation",
           "every shell part of a scene has the same kinematics in this version: expected the "
           "formulation of parts[0]");
    if (part.shell && !part.shell->reference.empty() &&
        part.section.formulation != Formulation::total_lagrangian)
      fail(s, pd["shell"]["reference"], path + ".shell.reference",
           "a curved reference is a finite-rotation shell: expected section.formulation: "
           "total_lagrangian (a small load step gives the linear response)");
    if (part.shell && !part.shell->reference.empty())
      check_regular_map(s, mesh, part, pd["shell"]["reference"], path + ".shell.reference");
    if (part.formulation != PartFormulation::displacement)
      fail(s, pd["formulation"], path + ".formulation",
           "a shell has no mixed_up formulation: expected displacement");
  }
  for (std::size_t i = 0; i < s.stages.size(); ++i) {
    const auto& stage = s.stages[i];
    if (stage.driver != "explicit") continue;
    if (stage.settings["transformation_traction"].as<bool>())
      fail(s, d["stages"][i]["transformation_traction"],
           "stages[" + std::to_string(i) + "].transformation_traction",
           "explicit shell stages hold their supports by Lagrange multipliers, which carry the "
           "reaction themselves (docs/shells.md): expected false");
  }
  const bool finite = s.parts.front().section.formulation == Formulation::total_lagrangian;
  for (std::size_t i = 0; i < s.boundary_conditions.size(); ++i) {
    const auto& bc = s.boundary_conditions[i];
    const auto path = "boundary_conditions[" + std::to_string(i) + "]";
    const auto& bd = d["boundary_conditions"][i];
    if (bc.type != "displacement")
      fail(s, bd["type"], path + ".type", "shell conditions prescribe displacements and rotations");
    // The weak methods' rotation terms would act on the step's rotation only (the frames carry
    // the rest) and their traction rows lack the finite-rotation terms.
    if (finite && bc.method != "transformation")
      fail(s, bd["method"], path + ".method",
           "with finite rotations (section formulation total_lagrangian) shells hold their "
           "supports by the transformation method: expected transformation");
    // With finite rotations a prescribed rotation turns the frames about one of their axes,
    // which that turn leaves in place, so the steps' rotations add up (docs/shells.md): the
    // other rotation held at 0.
    for (std::size_t c = 0; finite && c < 2; ++c) {
      const auto& r = bc.rotations[c];
      if (!r || (!r->varies() && r->constant == 0)) continue;
      const char* key = c == 0 ? "rx" : "ry";
      const char* other = c == 0 ? "ry" : "rx";
      const auto& o = bc.rotations[1 - c];
      if (!o || o->varies() || o->constant != 0)
        fail(s, bd[key], path + "." + key,
             std::string("with finite rotations a prescribed rotation turns about one axis: "
                         "expected ") +
                 other + ": 0 in the same condition");
    }
    if (bc.from_exact[0] || bc.from_exact[1] || bc.from_exact[2])
      fail(s, bd["from_exact_solution"], path + ".from_exact_solution",
           "shells have no exact-solution conditions; give the values");
  }
  for (std::size_t i = 0; i < s.loads.size(); ++i)
    if (s.loads[i].follower && !finite)
      fail(s, d["loads"][i]["follower"], "loads[" + std::to_string(i) + "].follower",
           "a follower pressure needs finite rotations (the shell parts' section.formulation: "
           "total_lagrangian); with small rotations the deformed normal is +z: expected false");
  for (std::size_t i = 0; i < s.loads.size(); ++i)
    if (s.loads[i].type != "shell_pressure" && s.loads[i].type != "shell_edge_load" &&
        s.loads[i].type != "shell_point_load")
      fail(s, d["loads"][i]["type"], "loads[" + std::to_string(i) + "].type",
           "shell parts take shell_pressure, shell_edge_load and shell_point_load loads in this "
           "version");
  check_shell_contacts(s);
  const std::pair<bool, const char*> unsupported[] = {
      {!s.initial_conditions.empty(), "initial_conditions"},
      {s.initial_state.has_value(), "initial_state"},
      {!s.rigid_walls.empty(), "rigid_walls"},
      {!s.angles.empty(), "angles"},
      {!s.exact_solution.empty() || s.user_solution.has_value(), "verification"},
      {!s.output.history_node_sets.empty(), "output.history_node_sets"}};
  for (const auto& [present, key] : unsupported)
    if (present) {
      const std::string k(key);
      const auto dot = k.find('.');
      const auto node = dot == std::string::npos ? d[k] : d[k.substr(0, dot)][k.substr(dot + 1)];
      fail(s, node, k, "not available with shell parts in this version");
    }
  const std::set<std::string> written = {"displacement", "nodal_volume",   "owner_rank", "stress",
                                         "resultants",   "plastic_strain", "thickness"};
  for (std::size_t i = 0; i < s.output.fields.size(); ++i)
    if (!written.count(s.output.fields[i]))
      fail(s, d["output"]["fields"][i], "output.fields[" + std::to_string(i) + "]",
           "shell runs write displacement (x, y, z), rotation (x, y), stress, resultants, "
           "thickness, plastic_strain, nodal_volume and owner_rank; '" +
               s.output.fields[i] + "' is a solid field");
}

}  // namespace efg
