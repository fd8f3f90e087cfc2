#include "scene/Schema.hpp"

#include <sstream>

namespace efg::schema {
namespace {
std::string number(double v) {
  std::ostringstream o;
  o << v;
  return o.str();
}
}  // namespace

std::string Spec::type_name() const {
  switch (type) {
    case Type::map:
      return "map";
    case Type::list:
      return "list of maps";
    case Type::real:
      return expression == ExpressionVariables::none       ? "real"
             : expression == ExpressionVariables::position ? "real or expression of x, y, z"
                                                           : "real or expression of x, y, z, t";
    case Type::integer:
      return "integer";
    case Type::boolean:
      return "boolean";
    case Type::string:
      return "string";
    case Type::choice:
      return "choice";
    case Type::real_list:
      if (expression != ExpressionVariables::none)
        return expression == ExpressionVariables::position
                   ? "list of reals or expressions of x, y, z"
                   : "list of reals or expressions of x, y, z, t";
      return scalar_allowed ? "real or list of reals" : "list of reals";
    case Type::integer_list:
      return "list of integers";
    case Type::string_list:
      return "list of strings";
    case Type::passthrough:
      return "map (passed to Trilinos)";
  }
  return "?";
}

std::string Spec::range_text() const {
  std::string text;
  if (min && max) {
    text = "in " + std::string(min_exclusive ? "(" : "[") + number(*min) + ", " + number(*max) +
           (max_exclusive ? ")" : "]");
  } else if (min) {
    text = (min_exclusive ? "> " : ">= ") + number(*min);
  } else if (max) {
    text = (max_exclusive ? "< " : "<= ") + number(*max);
  }
  return text;
}

Builder::Builder(Type type, std::string doc, std::string unit) {
  spec_.type = type;
  spec_.doc = std::move(doc);
  spec_.unit = std::move(unit);
}
Builder& Builder::at_least(double v) {
  spec_.min = v;
  spec_.min_exclusive = false;
  return *this;
}
Builder& Builder::above(double v) {
  spec_.min = v;
  spec_.min_exclusive = true;
  return *this;
}
Builder& Builder::at_most(double v) {
  spec_.max = v;
  spec_.max_exclusive = false;
  return *this;
}
Builder& Builder::below(double v) {
  spec_.max = v;
  spec_.max_exclusive = true;
  return *this;
}
Builder& Builder::choices(std::vector<std::string> c) {
  spec_.choices = std::move(c);
  return *this;
}
Builder& Builder::items(std::size_t min, std::size_t max) {
  spec_.min_items = min;
  spec_.max_items = max;
  return *this;
}
Builder& Builder::scalar_allowed() {
  spec_.scalar_allowed = true;
  return *this;
}
Builder& Builder::varying(ExpressionVariables variables) {
  spec_.expression = variables;
  return *this;
}
Builder& Builder::key(const std::string& name, SpecPtr spec, bool required, std::string def) {
  spec_.keys.push_back(Key{name, std::move(spec), required, std::move(def)});
  return *this;
}
Builder& Builder::discriminated_by(const std::string& key_name) {
  spec_.discriminator = key_name;
  return *this;
}
Builder& Builder::variant(const std::string& value, std::vector<Key> keys) {
  spec_.variants[value] = std::move(keys);
  return *this;
}
Builder& Builder::exactly_one_of(std::vector<std::string> names) {
  spec_.exactly_one_of.push_back(std::move(names));
  return *this;
}
Builder& Builder::at_least_one_of(std::vector<std::string> names) {
  spec_.at_least_one_of.push_back(std::move(names));
  return *this;
}
Builder& Builder::item(SpecPtr spec) {
  spec_.item = std::move(spec);
  return *this;
}
Builder& Builder::unique_names() {
  spec_.unique_names = true;
  return *this;
}

Builder map(std::string doc) {
  return Builder(Type::map, std::move(doc));
}
Builder list(std::string doc, SpecPtr item) {
  Builder b(Type::list, std::move(doc));
  b.item(std::move(item));
  return b;
}
Builder real(std::string doc, std::string unit) {
  return Builder(Type::real, std::move(doc), std::move(unit));
}
Builder integer(std::string doc) {
  return Builder(Type::integer, std::move(doc));
}
Builder boolean(std::string doc) {
  return Builder(Type::boolean, std::move(doc));
}
Builder string(std::string doc) {
  return Builder(Type::string, std::move(doc));
}
Builder choice(std::string doc, std::vector<std::string> values) {
  Builder b(Type::choice, std::move(doc));
  b.choices(std::move(values));
  return b;
}
Builder real_list(std::string doc, std::string unit) {
  return Builder(Type::real_list, std::move(doc), std::move(unit));
}
Builder integer_list(std::string doc) {
  return Builder(Type::integer_list, std::move(doc));
}
Builder string_list(std::string doc) {
  return Builder(Type::string_list, std::move(doc));
}
Builder passthrough(std::string doc) {
  return Builder(Type::passthrough, std::move(doc));
}

Key required_key(const std::string& name, SpecPtr spec) {
  return Key{name, std::move(spec), true, ""};
}
Key optional_key(const std::string& name, SpecPtr spec, std::string def) {
  return Key{name, std::move(spec), false, std::move(def)};
}

}  // namespace efg::schema
