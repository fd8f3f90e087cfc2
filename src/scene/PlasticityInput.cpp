#include "scene/PlasticityInput.hpp"

#include <cmath>
#include <sstream>

#include "core/Errors.hpp"
#include "materials/J2Plasticity.hpp"
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

}  // namespace

void check_plasticity_input(const Scene& s) {
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
    if (s.find_material(part.material)->model != "j2_plasticity") continue;
    const YAML::Node doc = s.document["parts"][i];
    // The history lives at the integration points; output reads it at the particle's own point
    // (SCNI, nodal) or averages the pieces of its domain (SCNI subcells). A Gauss point belongs
    // to no particle's domain (a projection is not built yet).
    if (part.section.integration == Integration::gauss)
      fail(s, doc["section"] ? doc["section"] : doc, "parts[" + std::to_string(i) + "].section",
           "part '" + part.name +
               "' has a j2_plasticity material: expected integration scni, scni_subcells or "
               "nodal (Gauss integration is not available for path-dependent materials yet)");
  }
  // The transformation and Nitsche methods add the boundary traction -integral phi_I (P n) over
  // the constrained boundary (Wagner & Liu 2000; docs/boundary_conditions.md), evaluated at
  // boundary points that carry no plastic history (operators/EssentialConditions computes P
  // with the elastic law there): on a uniaxial J2 block that wrong traction gave a
  // non-homogeneous solution with 2 % stress scatter, where penalty gives the closed form.
  bool plastic = false;
  for (const auto& m : s.materials) plastic = plastic || m.model == "j2_plasticity";
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
