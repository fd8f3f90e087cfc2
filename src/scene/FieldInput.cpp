#include "scene/FieldInput.hpp"

#include <memory>

#include "core/Errors.hpp"
#include "scene/SchemaValidator.hpp"

namespace efg {

ScalarField read_field(const Scene& scene, const YAML::Node& resolved, const YAML::Node& doc,
                       const std::string& path, ExpressionVariables variables) {
  ScalarField f;
  f.where = schema::located_message(scene.file, doc, path, "");
  f.where.erase(f.where.size() - 2);  // the empty message's ": "
  double v = 0;
  if (resolved.Tag() != "!" && YAML::convert<double>::decode(resolved, v)) {
    f.constant = v;
    return f;
  }
  auto e = std::make_shared<const Expression>(resolved.Scalar(), scene.parameters, variables);
  if (!e->uses_position() && !e->uses_time())
    f.constant = (*e)();
  else
    f.expression = std::move(e);
  return f;
}

std::vector<ScalarField> read_fields(const Scene& scene, const YAML::Node& resolved,
                                     const YAML::Node& doc, const std::string& path,
                                     ExpressionVariables variables) {
  std::vector<ScalarField> out;
  for (std::size_t i = 0; i < resolved.size(); ++i)
    out.push_back(
        read_field(scene, resolved[i], doc[i], path + "[" + std::to_string(i) + "]", variables));
  return out;
}

void read_user_solution(Scene& scene, const YAML::Node& v, const YAML::Node& doc) {
  const bool user = scene.exact_solution == "user";
  if (user != static_cast<bool>(v["user_solution"]))
    throw InputError(schema::located_message(
        scene.file, user ? doc["exact_solution"] : doc["user_solution"],
        user ? "verification.exact_solution" : "verification.user_solution",
        user ? "exact_solution user needs verification.user_solution (the displacement as "
               "expressions)"
             : "user_solution is read only with exact_solution: user"));
  if (!user) return;
  const auto at_x = ExpressionVariables::position;
  const auto& u = v["user_solution"];
  const auto& ud = doc["user_solution"];
  const std::string path = "verification.user_solution.";
  UserSolutionSpec spec;
  spec.displacement =
      read_fields(scene, u["displacement"], ud["displacement"], path + "displacement", at_x);
  if (u["body_force"])
    spec.body_force =
        read_fields(scene, u["body_force"], ud["body_force"], path + "body_force", at_x);
  if (u["stress"])
    for (const char* c : {"xx", "yy", "zz", "yz", "xz", "xy"})
      spec.stress.push_back(u["stress"][c] ? read_field(scene, u["stress"][c], ud["stress"][c],
                                                        path + "stress." + c, at_x)
                                           : ScalarField{});
  scene.user_solution = spec;
}

}  // namespace efg
