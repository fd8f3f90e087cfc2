#include "scene/ContactInput.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

#include "core/Errors.hpp"
#include "scene/SchemaValidator.hpp"
#include "scene/StageLists.hpp"

namespace efg {
namespace {

std::string shortest(double v) {
  std::ostringstream o;
  o << std::setprecision(3) << v;
  return o.str();
}

[[noreturn]] void fail(const Scene& s, const YAML::Node& at, const std::string& path,
                       const std::string& message) {
  throw InputError(schema::located_message(s.file, at, path, message));
}

std::vector<double> reals(const YAML::Node& n) {
  std::vector<double> v;
  if (n)
    for (const auto& x : n) v.push_back(x.as<double>());
  return v;
}

bool nonzero(const std::vector<double>& v) {
  double n2 = 0;
  for (double x : v) n2 += x * x;
  return n2 > 0;
}

RigidBodySpec read_body(const Scene& s, const YAML::Node& r, const YAML::Node& d,
                        const std::string& path) {
  RigidBodySpec b;
  b.name = r["name"].as<std::string>();
  b.shape = r["shape"].as<std::string>();
  b.motion = r["motion"].as<std::string>();
  b.point = reals(r["point"]);
  b.normal = reals(r["normal"]);
  b.center = reals(r["center"]);
  b.axis = reals(r["axis"]);
  b.radius = r["radius"] ? r["radius"].as<double>() : 0.0;
  b.lower = reals(r["lower"]);
  b.upper = reals(r["upper"]);
  b.velocity = reals(r["velocity"]);
  b.curve = r["curve"] ? r["curve"].as<std::string>() : "";
  b.thickness = r["thickness"].as<double>();
  b.gravity = reals(r["gravity"]);
  b.force = reals(r["force"]);
  b.angular_velocity = reals(r["angular_velocity"]);
  if (r["blocks"])
    for (const auto& n : r["blocks"]) b.blocks.push_back(n.as<std::string>());
  if (b.shape == "plane" && !nonzero(b.normal))
    fail(s, d["normal"], path + ".normal", "expected a nonzero normal");
  if (b.shape == "box")
    for (std::size_t k = 0; k < std::min(b.lower.size(), b.upper.size()); ++k)
      if (!(b.upper[k] > b.lower[k]))
        fail(s, d["upper"], path + ".upper",
             "expected every entry above the lower corner's (an empty box)");
  if (b.shape == "cylinder" && !b.axis.empty() && !nonzero(b.axis))
    fail(s, d["axis"], path + ".axis", "expected a nonzero axis");
  if (r["mass"] && r["density"])
    fail(s, d["density"], path + ".density", "give mass or density, not both");
  if (r["mass"]) b.mass = r["mass"].as<double>();
  if (r["density"]) b.density = r["density"].as<double>();
  if (b.motion == "free" && !(b.mass > 0) && !(b.density > 0))
    fail(s, d["motion"], path + ".motion",
         "a free rigid body needs mass or density (its motion follows from the contact forces)");
  if (b.motion == "prescribed" && b.velocity.empty())
    fail(s, d["motion"], path + ".motion", "a prescribed motion needs velocity");
  if (!b.curve.empty() && b.motion != "prescribed" && b.force.empty())
    fail(s, d["curve"], path + ".curve",
         "curve scales a prescribed velocity or a free body's force; motion is " + b.motion +
             (b.motion == "free" ? " without force" : ""));
  if (!b.curve.empty() && !s.find_curve(b.curve))
    fail(s, d["curve"], path + ".curve", "no curve named '" + b.curve + "' in curves");
  for (std::size_t k = 0; r["axis_curves"] && k < r["axis_curves"].size(); ++k) {
    const auto name = r["axis_curves"][k].as<std::string>();
    const auto key = path + ".axis_curves[" + std::to_string(k) + "]";
    if (b.motion != "prescribed")
      fail(s, d["axis_curves"], path + ".axis_curves",
           "axis_curves scale a prescribed velocity; motion is " + b.motion);
    if (!b.curve.empty())
      fail(s, d["axis_curves"], path + ".axis_curves", "give curve or axis_curves, not both");
    if (r["axis_curves"].size() != b.velocity.size())
      fail(s, d["axis_curves"], path + ".axis_curves",
           "expected one curve per velocity component (" + std::to_string(b.velocity.size()) +
               "), found " + std::to_string(r["axis_curves"].size()));
    if (!s.find_curve(name))
      fail(s, d["axis_curves"][k], key, "no curve named '" + name + "' in curves");
    b.axis_curves.push_back(name);
  }
  if (!b.angular_velocity.empty()) {
    const auto at = d["angular_velocity"];
    const auto key = path + ".angular_velocity";
    if (b.motion == "fixed")
      fail(s, at, key, "a fixed body does not turn; expected motion: free or prescribed");
    const bool box_2d = b.shape == "box" && b.lower.size() == 2;
    const bool cylinder_3d = b.shape == "cylinder" && b.center.size() == 3;
    if (b.shape == "plane")
      fail(s, at, key, "a plane does not turn; expected shape sphere, cylinder, box or mesh");
    // an infinite 3D cylinder has no inertia about an axis across it
    if (cylinder_3d && b.motion == "free")
      fail(s, at, key,
           "a free 3D cylinder (infinitely long) has no finite inertia to turn with; expected "
           "motion: prescribed (a driven roll), or a sphere or box");
    const std::size_t entries = b.center.size() == 2 || box_2d ? 1 : 3;
    // a mesh body's dimension is the mesh's: checked against it (scene/SceneMeshChecks)
    if (b.shape != "mesh" && b.angular_velocity.size() != entries)
      fail(s, at, key,
           "expected " + std::to_string(entries) + " entries (" +
               (entries == 1 ? "about z in 2D" : "a vector in 3D") + "), found " +
               std::to_string(b.angular_velocity.size()));
  }
  if (!b.force.empty() && b.motion != "free")
    fail(s, d["force"], path + ".force",
         "an applied force moves free bodies only; motion is " + b.motion +
             "; expected motion: free");
  if (!b.gravity.empty() && b.motion != "free")
    fail(s, d["gravity"], path + ".gravity",
         "gravity moves free bodies only; motion is " + b.motion + "; expected motion: free");
  if (b.motion == "fixed" && !b.velocity.empty())
    fail(s, d["velocity"], path + ".velocity",
         "a fixed body has no velocity; expected motion prescribed or free");
  return b;
}

ContactSpec read_contact(const Scene& s, const YAML::Node& r, const YAML::Node& d,
                         const std::string& path) {
  ContactSpec c;
  c.name = r["name"].as<std::string>();
  if (r["rigid_body"]) c.rigid_body = r["rigid_body"].as<std::string>();
  c.two_way = r["two_way"].as<bool>();
  c.penalty = r["penalty"].as<double>();
  c.static_friction = r["static_friction"].as<double>();
  c.dynamic_friction =
      r["dynamic_friction"] ? r["dynamic_friction"].as<double>() : c.static_friction;
  c.decay = r["decay"].as<double>();
  c.damping = r["damping"].as<double>();
  c.implicit_penalty = r["implicit_penalty"].as<double>();
  c.penalty_scale = r["penalty_scale"].as<double>();
  c.penetration_warning = r["penetration_warning"].as<double>();
  c.initial_penetration = r["initial_penetration"].as<std::string>();
  for (const auto& name : r["stages"]) c.stages.names.push_back(name.as<std::string>());
  auto is_body = [&](const std::string& n) {
    return std::any_of(s.rigid_bodies.begin(), s.rigid_bodies.end(),
                       [&](const RigidBodySpec& b) { return b.name == n; });
  };
  auto is_part = [&](const std::string& n) {
    return std::any_of(s.parts.begin(), s.parts.end(),
                       [&](const PartSpec& p) { return p.name == n; });
  };
  if (!c.rigid_body.empty() && !is_body(c.rigid_body))
    fail(s, d["rigid_body"], path + ".rigid_body",
         is_part(c.rigid_body)
             ? "'" + c.rigid_body +
                   "' is a deformable part; expected a rigid body (a deformable part's surface "
                   "is touched through target_parts)"
             : "no rigid body named '" + c.rigid_body + "' in rigid_bodies");
  // Parts and target parts: meshfree parts, each named once; a part touching its own surface
  // (self-contact) is not built.
  auto read_parts = [&](const char* key, std::vector<std::string>& out) {
    if (!r[key]) return;  // target_parts of a contact with a rigid body
    for (std::size_t i = 0; i < r[key].size(); ++i) {
      const auto name = r[key][i].as<std::string>();
      const auto at = d[key][i];
      const auto where = path + "." + key + "[" + std::to_string(i) + "]";
      if (is_body(name))
        fail(s, at, where,
             "'" + name +
                 "' is a rigid body: contact between two rigid bodies is not modeled; "
                 "expected a meshfree part");
      if (!is_part(name)) fail(s, at, where, "no part named '" + name + "' in parts");
      if (std::find(c.parts.begin(), c.parts.end(), name) != c.parts.end())
        fail(s, at, where,
             "'" + name +
                 "' is named twice: self-contact is not built; expected parts and target_parts "
                 "without a part in common");
      out.push_back(name);
    }
  };
  read_parts("parts", c.parts);
  read_parts("target_parts", c.target_parts);
  // Between deformable parts P = 4 penalty two-way, 2 penalty one-way is kept up to 1 (the
  // rigid walls' default): two bars meeting two-way at penalty 0.35 (P = 1.4) ring by +-35 %
  // and at 0.5 blow up.
  const double most = c.two_way ? 0.25 : 0.5;
  if (!c.target_parts.empty() && c.penalty > most)
    fail(s, d["penalty"], path + ".penalty",
         "a " + std::string(c.two_way ? "two-way " : "") +
             "contact between deformable parts takes a penalty up to " +
             (c.two_way ? "0.25" : "0.5") +
             " (its springs join two moving particles); expected a smaller value");
  // The stable step falls by sqrt(1 - share / 4): keep it above half the elastic one.
  if (contact_stability_share(c) > 3.0)
    fail(s, d["damping"] ? d["damping"] : d["penalty"],
         path + (d["damping"] ? ".damping" : ".penalty"),
         "penalty and damping together would cut the stable time step below half the elastic "
         "one (their share in the stability condition is " +
             shortest(contact_stability_share(c)) +
             " of at most 3, docs/contact.md); expected a smaller damping or penalty");
  return c;
}

// A free body in an implicit (static) stage is force-controlled (drivers/BodyForceBalance): it
// moves along its load only, so it needs a load with one direction and no spin to integrate.
void check_static_load(const Scene& s, const RigidBodySpec& b, const ContactSpec& c,
                       const YAML::Node& stage_at, const std::string& stage_key) {
  const auto i = static_cast<std::size_t>(&b - s.rigid_bodies.data());
  const auto path = "rigid_bodies[" + std::to_string(i) + "]";
  const auto& d = s.document["rigid_bodies"][i];
  const auto who = "rigid body '" + b.name + "' of contact '" + c.name + "'";
  if (!b.angular_velocity.empty())
    fail(s, stage_at, stage_key,
         who +
             " is free and turns, which implicit stages do not model yet; expected driver: "
             "explicit, or no angular_velocity");
  const auto size = [](const std::vector<double>& v) {
    double n = 0;
    for (double x : v) n += x * x;
    return std::sqrt(n);
  };
  const double f = size(b.force), g = size(b.gravity);
  if (!(f > 0) && !(g > 0))
    fail(s, d["motion"], path + ".motion",
         who +
             " is free in an implicit (static) stage, where it is placed to balance its load, "
             "but it has none; expected force: (a blank holder's) or gravity:, or motion: "
             "fixed or prescribed");
  if (f > 0 && g > 0) {
    double dot = 0;
    for (std::size_t k = 0; k < std::min(b.force.size(), b.gravity.size()); ++k)
      dot += b.force[k] * b.gravity[k];
    if (std::abs(std::abs(dot) - f * g) > 1e-12 * f * g)
      fail(s, d["gravity"], path + ".gravity",
           who +
               " moves along its load in an implicit (static) stage, but its force and gravity "
               "point different ways; expected them parallel");
  }
}

}  // namespace

double contact_stability_share(const ContactSpec& c) {
  const double root = std::sqrt(c.penalty);
  if (c.target_parts.empty()) return c.penalty + 2.0 * (2.0 * c.damping * root);
  if (c.two_way) return 4.0 * c.penalty + 2.0 * (4.0 * c.damping * root);
  return 2.0 * c.penalty + 2.0 * (2.0 * std::sqrt(2.0) * c.damping * root);
}

double rigid_body_volume(const RigidBodySpec& b, int dim) {
  constexpr double pi = 3.14159265358979323846;
  const bool two_d = dim == 2;
  if (b.shape == "mesh") return b.surface ? b.surface->volume * (two_d ? b.thickness : 1.0) : 0.0;
  if (b.shape == "sphere")
    return two_d ? pi * b.radius * b.radius * b.thickness
                 : 4.0 / 3.0 * pi * b.radius * b.radius * b.radius;
  if (b.shape == "cylinder" && two_d) return pi * b.radius * b.radius * b.thickness;
  if (b.shape == "box") {
    double v = two_d ? b.thickness : 1.0;
    for (std::size_t k = 0; k < b.lower.size(); ++k) v *= b.upper[k] - b.lower[k];
    return v;
  }
  return 0.0;
}

void read_contact_input(Scene& s) {
  const auto& r = s.resolved;
  const auto& d = s.document;
  for (std::size_t i = 0; i < r["rigid_bodies"].size(); ++i) {
    const auto path = "rigid_bodies[" + std::to_string(i) + "]";
    s.rigid_bodies.push_back(read_body(s, r["rigid_bodies"][i], d["rigid_bodies"][i], path));
    // Refused here, before any mesh is read: a shell surface read in 3D with the body's cells in
    // the same file would otherwise meet the surface checks first on one read path and this
    // refusal on the other.
    if (s.rigid_bodies.back().shape == "mesh" && s.has_shells())
      fail(s, d["rigid_bodies"][i]["blocks"], path + ".blocks",
           "rigid bodies of mesh blocks touch solid parts only for now; expected an analytic "
           "shape with shell parts");
  }
  for (std::size_t i = 0; i < r["contacts"].size(); ++i)
    s.contacts.push_back(
        read_contact(s, r["contacts"][i], d["contacts"][i], "contacts[" + std::to_string(i) + "]"));
  // Implicit stages: contact with fixed, prescribed or force-controlled (free) bodies, with or
  // without friction; between deformable parts too.
  std::vector<std::string> stage_names;
  for (const auto& st : s.stages) stage_names.push_back(st.name);
  for (std::size_t i = 0; i < s.contacts.size(); ++i)
    check_stage_list(s, stage_names, s.contacts[i].stages, "contacts", i);
  // What implicit stages cannot model yet, for each contact active in one.
  for (std::size_t i = 0; i < s.contacts.size(); ++i) {
    const auto& c = s.contacts[i];
    std::size_t implicit = s.stages.size();
    for (std::size_t k = 0; k < s.stages.size() && implicit == s.stages.size(); ++k)
      if (s.stages[k].driver == "implicit" && c.stages.includes(s.stages[k].name)) implicit = k;
    if (implicit == s.stages.size()) continue;
    const auto stage_key = "stages[" + std::to_string(implicit) + "].driver";
    const YAML::Node stage_at = d["stages"][implicit]["driver"];
    const auto path = "contacts[" + std::to_string(i) + "]";
    for (const auto& b : s.rigid_bodies) {
      if (b.name != c.rigid_body) continue;
      if (b.motion == "free") check_static_load(s, b, c, stage_at, stage_key);
      // A springback stage releases the forces out of balance at its start, the body's too,
      // while force control balances the body's load in full (drivers/BodyForceBalance).
      for (std::size_t k = 0; k < s.stages.size() && b.motion == "free"; ++k) {
        const auto& st = s.stages[k];
        if (st.driver == "implicit" && c.stages.includes(st.name) && st.settings["springback"] &&
            st.settings["springback"].as<bool>())
          fail(s, d["stages"][k]["springback"], "stages[" + std::to_string(k) + "].springback",
               "contact '" + c.name + "' with the free (force-controlled) rigid body '" + b.name +
                   "' acts in springback stage '" + st.name +
                   "', which releases what holds the parts; expected the contact's stages: to "
                   "leave it out (" +
                   path + ".stages), or motion: fixed or prescribed");
      }
    }
  }
}

}  // namespace efg
