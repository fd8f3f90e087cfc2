#include "scene/PlasticityInput.hpp"

#include <cmath>
#include <sstream>

#include "core/Errors.hpp"
#include "materials/CrushableFoam.hpp"
#include "materials/J2Plasticity.hpp"
#include "materials/LowDensityFoam.hpp"
#include "scene/SchemaValidator.hpp"

namespace efg {
namespace {

[[noreturn]] void fail(const Scene& s, const YAML::Node& at, const std::string& path,
                       const std::string& message) {
  throw InputError(schema::located_message(s.file, at, path, message));
}

std::string number(double x) {
  std::ostringstream o;
  o << x;
  return o.str();
}

void check_curve(const Scene& s, const MaterialSpec& m, const YAML::Node& doc,
                 const std::string& path) {
  const YAML::Node at = doc["hardening_curve"];
  const std::string key = path + ".hardening_curve";
  if (m.constants.count("hardening_modulus"))
    fail(s, at, key, "give hardening_modulus or hardening_curve, not both");
  const CurveSpec* c = s.find_curve(m.hardening_curve);
  if (!c) fail(s, at, key, "no curve named '" + m.hardening_curve + "' in curves");
  const double yield = m.constants.at("yield_stress");
  if (c->time.empty() || c->time[0] != 0.0 ||
      std::abs(c->value[0] - yield) > 1e-12 * std::abs(yield))
    fail(s, at, key,
         "curve '" + c->name + "' must start at plastic strain 0 with the yield stress " +
             number(yield) + ", found (" + (c->time.empty() ? "no points" : number(c->time[0])) +
             (c->time.empty() ? "" : ", " + number(c->value[0])) + ")");
  if (c->time.size() > physics::J2Parameters::max_curve_points + 1)
    fail(s, at, key,
         "curve '" + c->name + "' has " + std::to_string(c->time.size()) + " points; at most " +
             std::to_string(physics::J2Parameters::max_curve_points + 1) + " are supported");
  for (std::size_t i = 1; i < c->time.size(); ++i)
    if (c->value[i] < c->value[i - 1])
      fail(s, at, key,
           "curve '" + c->name + "' decreases from " + number(c->value[i - 1]) + " to " +
               number(c->value[i]) + " at plastic strain " + number(c->time[i]) +
               ": softening is not supported; expected a yield stress that does not decrease");
}

// The crushable foam's yield curve: sigma_y over the volumetric strain 1 - J, which lies in
// (-inf, 1) for J > 0; the law reads it from 0 on (constant below) and needs sigma_y > 0 (a
// zero compressive strength crushes at no load).
void check_yield_curve(const Scene& s, const MaterialSpec& m, const YAML::Node& doc,
                       const std::string& path) {
  const YAML::Node at = doc["yield_curve"];
  const std::string key = path + ".yield_curve";
  const CurveSpec* c = s.find_curve(m.yield_curve);
  if (!c) fail(s, at, key, "no curve named '" + m.yield_curve + "' in curves");
  const std::string curve = "curve '" + c->name + "' ";
  if (c->time.size() > physics::CrushableFoamParameters::max_curve_points)
    fail(s, at, key,
         curve + "has " + std::to_string(c->time.size()) + " points; at most " +
             std::to_string(physics::CrushableFoamParameters::max_curve_points) + " are supported");
  if (c->time.empty() || c->time[0] != 0.0)
    fail(s, at, key,
         curve + "must start at volumetric strain 0, found " +
             (c->time.empty() ? "no points" : number(c->time[0])));
  for (std::size_t i = 0; i < c->time.size(); ++i) {
    if (i > 0 && !(c->time[i] > c->time[i - 1]))
      fail(s, at, key,
           curve + "is not increasing in volumetric strain: " + number(c->time[i - 1]) + " then " +
               number(c->time[i]) + "; expected strictly increasing strains");
    if (!(c->time[i] < 1.0))
      fail(s, at, key,
           curve + "reaches volumetric strain " + number(c->time[i]) +
               "; expected strains below 1 (1 - J < 1 for every J > 0)");
    if (!(c->value[i] > 0.0))
      fail(s, at, key,
           curve + "has yield stress " + number(c->value[i]) + " at volumetric strain " +
               number(c->time[i]) + "; expected a positive compressive yield stress");
  }
}

// The low-density foam's loading curve: nominal compressive stress over the nominal strain
// 1 - lambda, which lies in (-inf, 1) for lambda > 0. It starts at the unloaded state (0, 0)
// and may not fall (the unloading factor and the stiffness bound assume f' >= 0,
// LowDensityFoam.hpp).
void check_loading_curve(const Scene& s, const MaterialSpec& m, const YAML::Node& doc,
                         const std::string& path) {
  const YAML::Node at = doc["loading_curve"];
  const std::string key = path + ".loading_curve";
  const CurveSpec* c = s.find_curve(m.loading_curve);
  if (!c) fail(s, at, key, "no curve named '" + m.loading_curve + "' in curves");
  const std::string curve = "curve '" + c->name + "' ";
  const std::size_t most = physics::LowDensityFoamParameters::max_curve_points;
  if (c->time.size() > most)
    fail(s, at, key,
         curve + "has " + std::to_string(c->time.size()) + " points; at most " +
             std::to_string(most) + " are supported");
  if (c->time.size() < 2)
    fail(s, at, key,
         curve + "has " + std::to_string(c->time.size()) +
             " point(s); expected at least 2 (from (0, 0) on)");
  if (c->time[0] != 0.0 || c->value[0] != 0.0)
    fail(s, at, key,
         curve + "starts at (" + number(c->time[0]) + ", " + number(c->value[0]) +
             "); expected the first point at nominal strain 0 and stress 0");
  for (std::size_t i = 1; i < c->time.size(); ++i) {
    if (!(c->time[i] > c->time[i - 1]))
      fail(s, at, key,
           curve + "is not increasing in nominal strain: " + number(c->time[i - 1]) + " then " +
               number(c->time[i]) + "; expected strictly increasing strains");
    if (!(c->time[i] < 1.0))
      fail(s, at, key,
           curve + "reaches nominal strain " + number(c->time[i]) +
               "; expected strains below 1 (1 - lambda < 1 for every stretch lambda > 0)");
    if (!(c->value[i] >= c->value[i - 1]))
      fail(s, at, key,
           curve + "decreases: stress " + number(c->value[i - 1]) + " then " + number(c->value[i]) +
               " at nominal strain " + number(c->time[i]) +
               "; expected a nominal stress that does not decrease");
  }
  if (!(c->value.back() > 0.0))
    fail(s, at, key, curve + "carries no stress; expected a positive nominal stress somewhere");
}

void check_foam(const Scene& s, std::size_t i) {
  const auto& m = s.materials[i];
  const std::string path = "materials[" + std::to_string(i) + "]";
  if (m.model == "low_density_foam")
    check_loading_curve(s, m, s.document["materials"][i], path);
  else
    check_yield_curve(s, m, s.document["materials"][i], path);
  // The law's tangent is its elastic one (operators/MaterialTangent.hpp): right for the explicit
  // stable step, not for Newton.
  for (const auto& st : s.stages)
    if (st.driver != "explicit")
      fail(s, s.document["materials"][i]["model"], path + ".model",
           "model " + m.model +
               " runs in explicit stages only (it has no consistent tangent), "
               "but stage '" +
               st.name + "' is " + st.driver + "; expected explicit stages");
  for (std::size_t k = 0; k < s.parts.size(); ++k) {
    const auto& part = s.parts[k];
    if (part.material != m.name) continue;
    const YAML::Node doc = s.document["parts"][k];
    const std::string at = "parts[" + std::to_string(k) + "]";
    if (part.formulation == PartFormulation::mixed_up)
      fail(s, doc["formulation"], at + ".formulation",
           "part '" + part.name + "' has a " + m.model +
               " material, which has no volumetric-deviatoric split: "
               "expected formulation displacement");
    if (part.plane_stress)
      fail(s, doc["plane_stress"] ? doc["plane_stress"] : doc, at + ".plane_stress",
           "part '" + part.name + "' has a " + m.model +
               " material: expected plane strain or 3D (plane stress is "
               "not available for it)");
  }
}

}  // namespace

void check_plasticity_input(const Scene& s) {
  for (std::size_t i = 0; i < s.materials.size(); ++i)
    if (s.materials[i].model == "crushable_foam" || s.materials[i].model == "low_density_foam")
      check_foam(s, i);
  for (std::size_t i = 0; i < s.materials.size(); ++i) {
    const auto& m = s.materials[i];
    if (m.model != "j2_plasticity") continue;
    const std::string path = "materials[" + std::to_string(i) + "]";
    if (!m.hardening_curve.empty()) check_curve(s, m, s.document["materials"][i], path);
    if (m.constants.count("failure_strain"))
      for (const auto& st : s.stages)
        if (st.driver == "implicit")
          fail(s, s.document["materials"][i]["failure_strain"], path + ".failure_strain",
               "erosion removes particles during explicit stages only, but stage '" + st.name +
                   "' is implicit; expected no failure_strain, or explicit stages");
  }
  for (std::size_t i = 0; i < s.parts.size(); ++i) {
    const auto& part = s.parts[i];
    if (!s.find_material(part.material)->path_dependent()) continue;
    const YAML::Node doc = s.document["parts"][i];
    // The history lives at the integration points; output reads it at the particle's own point
    // (SCNI, nodal) or averages the pieces of its domain (SCNI subcells). A Gauss point belongs
    // to no particle's domain (a projection is not built yet).
    if (part.section.integration == Integration::gauss)
      fail(s, doc["section"] ? doc["section"] : doc, "parts[" + std::to_string(i) + "].section",
           "part '" + part.name + "' has a " + s.find_material(part.material)->model +
               " material: expected integration scni, scni_subcells or "
               "nodal (Gauss integration is not available for path-dependent materials yet)");
  }
  // The transformation and Nitsche methods add the boundary traction -integral phi_I (P n) over
  // the constrained boundary (Wagner & Liu 2000; docs/boundary_conditions.md), evaluated at
  // boundary points that carry no plastic history (operators/EssentialConditions computes P
  // with the elastic law there): on a uniaxial J2 block that wrong traction gave a
  // non-homogeneous solution with 2 % stress scatter, where penalty gives the closed form.
  bool plastic = false;
  for (const auto& m : s.materials) plastic = plastic || m.path_dependent();
  bool implicit = false;  // explicit stages prescribe the motion of the particles directly
  for (const auto& st : s.stages) implicit = implicit || st.driver == "implicit";
  for (std::size_t b = 0; plastic && implicit && b < s.boundary_conditions.size(); ++b) {
    const auto& method = s.boundary_conditions[b].method;
    if (method != "nitsche" || s.boundary_conditions[b].type != "displacement") continue;
    const YAML::Node bc = s.document["boundary_conditions"][b];
    fail(s, bc["method"] ? bc["method"] : bc,
         "boundary_conditions[" + std::to_string(b) + "].method",
         "method " + method + " is not available with a j2_plasticity material (" +
             "its symmetric term is built for elastic laws" +
             "); expected method transformation or penalty");
  }
}

}  // namespace efg
