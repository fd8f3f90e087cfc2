#include "scene/SchemaValidator.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <regex>
#include <set>
#include <sstream>

#include "core/Errors.hpp"
#include "scene/Suggest.hpp"

namespace efg::schema {

std::string located_message(const std::string& file, const YAML::Node& node,
                            const std::string& path, const std::string& message,
                            int column_offset) {
  std::ostringstream o;
  o << file;
  if (node.IsDefined()) {  // a key the document lacks has no line to point at
    const auto mark = node.Mark();
    if (mark.line >= 0) o << ":" << mark.line + 1 << ":" << mark.column + 1 + column_offset;
  }
  o << ": " << (path.empty() ? "(top level)" : path) << ": " << message;
  return o.str();
}

namespace {

std::string join(const std::vector<std::string>& words, const std::string& sep = ", ") {
  std::string s;
  for (std::size_t i = 0; i < words.size(); ++i) s += (i ? sep : "") + words[i];
  return s;
}

std::string child_path(const std::string& parent, const std::string& key) {
  return parent.empty() ? key : parent + "." + key;
}

std::string describe_found(const YAML::Node& node) {
  if (!node.IsDefined() || node.IsNull()) return "nothing";
  if (node.IsMap()) return "a map";
  if (node.IsSequence()) return "a list";
  return "'" + node.Scalar() + "'";
}

bool is_quoted(const YAML::Node& node) {
  return node.Tag() == "!";
}

}  // namespace

int expression_column_offset(const YAML::Node& node, int position) {
  return (is_quoted(node) ? 1 : 0) + std::max(0, position);
}

bool is_non_decimal_integer(const YAML::Node& node) {
  long long i = 0;
  if (!node.IsScalar() || is_quoted(node) || !YAML::convert<long long>::decode(node, i))
    return false;
  static const std::regex decimal("[-+]?(0|[1-9][0-9]*)");
  return !std::regex_match(node.Scalar(), decimal);
}

namespace {

const std::set<std::string>& reserved_parameter_names() {
  static const std::set<std::string> names = {
      "x",    "y",    "z",     "t",    "pi",   "_pi",  "_e",    "sin",   "cos",   "tan", "asin",
      "acos", "atan", "atan2", "sinh", "cosh", "tanh", "asinh", "acosh", "atanh", "exp", "ln",
      "log",  "log2", "log10", "sqrt", "abs",  "sign", "rint",  "min",   "max",   "sum", "avg"};
  return names;
}

std::string first_sentence(const std::string& doc) {
  const auto end = doc.find(". ");
  return end == std::string::npos ? doc : doc.substr(0, end + 1);
}

class Validator {
 public:
  explicit Validator(std::string file) : file_(std::move(file)) {}

  /// parameters: name -> number or expression of the earlier parameters, in file order.
  YAML::Node read_parameters(const YAML::Node& node) {
    YAML::Node out(YAML::NodeType::Map);
    if (!node || node.IsNull()) return out;
    if (!node.IsMap())
      fail(node, "parameters",
           "expected a map of named numbers (name: value), found " + describe_found(node));
    for (const auto& kv : node) {
      const auto name = kv.first.Scalar();
      const auto path = "parameters." + name;
      static const std::regex identifier("[A-Za-z][A-Za-z0-9_]*");
      if (!std::regex_match(name, identifier))
        fail(kv.first, path, "a parameter name starts with a letter and has letters, digits, _");
      if (reserved_parameter_names().count(name))
        fail(kv.first, path,
             "'" + name + "' is a variable or function of expressions; choose another name");
      if (parameters_.count(name))
        fail(kv.first, path, "parameter '" + name + "' is defined twice");
      if (!kv.second.IsScalar())
        fail(kv.second, path,
             "expected a real or an expression of earlier parameters, found " +
                 describe_found(kv.second));
      const double v =
          constant_value(kv.second, path, "a real or an expression of earlier parameters");
      parameters_[name] = v;
      out[name] = v;
    }
    return out;
  }

  YAML::Node check(const YAML::Node& node, const Spec& spec, const std::string& path) {
    switch (spec.type) {
      case Type::map:
        return check_map(node, spec, path);
      case Type::list:
        return check_list(node, spec, path);
      case Type::passthrough:
        if (!node.IsNull() && !node.IsMap())
          fail(node, path, "expected a map of solver parameters, found " + describe_found(node));
        refuse_non_decimal_integers(node, path);
        return node.IsNull() ? YAML::Node(YAML::NodeType::Map) : YAML::Clone(node);
      case Type::real_list:
      case Type::integer_list:
      case Type::string_list:
        return check_scalar_list(node, spec, path);
      default:
        return check_scalar(node, spec, path);
    }
  }

 private:
  [[noreturn]] void fail(const YAML::Node& node, const std::string& path,
                         const std::string& message) const {
    throw InputError(located_message(file_, node, path, message));
  }

  // Solver maps go to Trilinos untyped (ParameterListFromYaml): an integer there is read by
  // yaml-cpp too, so 0x10 and 010 are refused here, where the written text has its lines.
  void refuse_non_decimal_integers(const YAML::Node& node, const std::string& path) const {
    if (is_non_decimal_integer(node)) fail(node, path, non_decimal_message(node, ""));
    if (node.IsMap())
      for (const auto& kv : node)
        refuse_non_decimal_integers(kv.second, child_path(path, kv.first.Scalar()));
    else if (node.IsSequence())
      for (std::size_t i = 0; i < node.size(); ++i)
        refuse_non_decimal_integers(node[i], path + "[" + std::to_string(i) + "]");
  }

  static std::string non_decimal_message(const YAML::Node& node, const std::string& range) {
    return "expected a decimal integer" + (range.empty() ? "" : " " + range) + ", found '" +
           node.Scalar() + "' (hexadecimal, octal and leading zeros are not read)";
  }

  YAML::Node check_scalar(const YAML::Node& node, const Spec& spec, const std::string& path) {
    const std::string expected = "expected " + article(spec) + describe_expected(spec);
    if (!node.IsScalar()) fail(node, path, expected + ", found " + describe_found(node));
    switch (spec.type) {
      case Type::real: {
        double v = 0;
        if (spec.expression != ExpressionVariables::none) {
          if (check_varying(node, spec, path, v)) return YAML::Clone(node);  // stays text
          const bool below = spec.min && (spec.min_exclusive ? v <= *spec.min : v < *spec.min);
          const bool above = spec.max && (spec.max_exclusive ? v >= *spec.max : v > *spec.max);
          if (below || above)
            fail(node, path,
                 "expected a finite real " + spec.range_text() + ", found " + node.Scalar());
          return is_plain_number(node) ? YAML::Clone(node) : YAML::Node(v);
        }
        v = check_number(node, spec, path, false);
        return is_plain_number(node) ? YAML::Clone(node) : YAML::Node(v);
      }
      case Type::integer: {
        const double v = check_number(node, spec, path, true);
        return is_plain_number(node) ? YAML::Clone(node) : YAML::Node(static_cast<long long>(v));
      }
      case Type::boolean: {
        bool b = false;
        if (is_quoted(node) || !YAML::convert<bool>::decode(node, b))
          fail(node, path, expected + ", found " + describe_found(node));
        break;
      }
      case Type::choice:
        check_choice(node, spec, path);
        break;
      default:
        break;
    }
    return YAML::Clone(node);
  }

  static bool is_plain_number(const YAML::Node& node) {
    double v = 0;
    return !is_quoted(node) && YAML::convert<double>::decode(node, v);
  }

  static std::string article(const Spec& spec) {
    return spec.type == Type::integer ? "an " : (spec.type == Type::choice ? "" : "a ");
  }

  static std::string describe_expected(const Spec& spec) {
    if (spec.type == Type::choice) return "one of " + join(spec.choices);
    std::string text = spec.type_name();
    if (!spec.range_text().empty()) text += " " + spec.range_text();
    return text;
  }

  // The value of a constant expression (numbers and parameters); fails at the offending
  // character with `expected` and the reason.
  double constant_value(const YAML::Node& node, const std::string& path,
                        const std::string& expected) {
    const double v = compile(node, path, expected, ExpressionVariables::none)();
    if (!std::isfinite(v))
      fail(node, path,
           "expected " + expected + ", found '" + node.Scalar() + "' = " + std::to_string(v) +
               " (not finite)");
    return v;
  }

  // The scalar compiled as an expression; a compile error fails at its faulty character.
  Expression compile(const YAML::Node& node, const std::string& path, const std::string& expected,
                     ExpressionVariables variables) const {
    try {
      return Expression(node.Scalar(), parameters_, variables);
    } catch (const ExpressionError& e) {
      throw InputError(
          located_message(file_, node, path,
                          "expected " + expected + ", found '" + node.Scalar() + "': " + e.what(),
                          expression_column_offset(node, e.position())));
    }
  }

  // A key that may vary: a number, a constant expression (resolved to its value) or an expression
  // of the allowed variables (kept as text; evaluated at points by the scene/mesh checks).
  // Returns true when the text stays an expression.
  bool check_varying(const YAML::Node& node, const Spec& spec, const std::string& path,
                     double& value) {
    double number = 0;
    if (!is_quoted(node) && YAML::convert<double>::decode(node, number) && std::isfinite(number)) {
      value = number;
      return false;
    }
    const std::string expected =
        "a finite real or an expression of " +
        std::string(spec.expression == ExpressionVariables::position ? "x, y, z" : "x, y, z, t") +
        " and the parameters";
    const auto e = compile(node, path, expected, spec.expression);
    if (e.uses_position() || e.uses_time()) return true;
    value = constant_value(node, path, expected);
    return false;
  }

  double check_number(const YAML::Node& node, const Spec& spec, const std::string& path,
                      bool integral) {
    double value = 0;
    bool ok = !is_quoted(node);
    if (ok && integral && is_non_decimal_integer(node))
      fail(node, path, non_decimal_message(node, spec.range_text()));
    if (ok && integral) {
      long long i = 0;
      ok = YAML::convert<long long>::decode(node, i);
      value = static_cast<double>(i);
    } else if (ok) {
      ok = YAML::convert<double>::decode(node, value) && std::isfinite(value);
    }
    const std::string expected = std::string("expected ") +
                                 (integral ? "an integer" : "a finite real") +
                                 (spec.range_text().empty() ? "" : " " + spec.range_text());
    double plain = 0;
    const bool plain_number = !is_quoted(node) && YAML::convert<double>::decode(node, plain);
    if (!ok && !plain_number) {  // text: an expression of the parameters
      value = constant_value(node, path,
                             std::string(integral ? "an integer" : "a finite real") +
                                 (spec.range_text().empty() ? "" : " " + spec.range_text()) +
                                 " or an expression of the parameters");
      ok = !integral || value == std::round(value);
    }
    if (!ok) fail(node, path, expected + ", found " + describe_found(node));
    const bool below = spec.min && (spec.min_exclusive ? value <= *spec.min : value < *spec.min);
    const bool above = spec.max && (spec.max_exclusive ? value >= *spec.max : value > *spec.max);
    if (below || above) fail(node, path, expected + ", found " + node.Scalar());
    // Integers are read as 32-bit ints unless the key sets its own bound (counts, seeds, ...).
    constexpr double kIntMax = 2147483647.0;
    if (integral && !spec.max && (value > kIntMax || value < -kIntMax - 1))
      fail(node, path,
           expected + " that fits in 32 bits (at most 2147483647), found " + node.Scalar());
    return value;
  }

  void check_choice(const YAML::Node& node, const Spec& spec, const std::string& path) {
    const auto& v = node.Scalar();
    for (const auto& c : spec.choices)
      if (c == v) return;
    std::string message = "'" + v + "' is not one of " + join(spec.choices);
    if (auto s = closest_match(v, spec.choices)) message += " (did you mean '" + *s + "'?)";
    fail(node, path, message);
  }

  YAML::Node check_scalar_list(const YAML::Node& node, const Spec& spec, const std::string& path) {
    YAML::Node items(YAML::NodeType::Sequence);
    std::vector<YAML::Node> given;
    if (node.IsSequence()) {
      for (const auto& item : node) given.push_back(item);
    } else if (node.IsScalar() && spec.scalar_allowed) {
      given.push_back(node);
    } else {
      fail(node, path, "expected a " + spec.type_name() + ", found " + describe_found(node));
    }
    if (given.size() < spec.min_items || given.size() > spec.max_items) {
      std::string count =
          spec.min_items == spec.max_items
              ? std::to_string(spec.min_items)
              : (spec.max_items == std::numeric_limits<std::size_t>::max()
                     ? "at least " + std::to_string(spec.min_items)
                     : std::to_string(spec.min_items) + " to " + std::to_string(spec.max_items));
      fail(node, path, "expected " + count + " entries, found " + std::to_string(given.size()));
    }
    Spec item = spec;
    item.type = spec.type == Type::real_list      ? Type::real
                : spec.type == Type::integer_list ? Type::integer
                : spec.choices.empty()            ? Type::string
                                                  : Type::choice;
    for (std::size_t i = 0; i < given.size(); ++i)
      items.push_back(check_scalar(given[i], item, path + "[" + std::to_string(i) + "]"));
    return items;
  }

  YAML::Node check_list(const YAML::Node& node, const Spec& spec, const std::string& path) {
    YAML::Node out(YAML::NodeType::Sequence);
    if (node.IsNull()) return out;
    if (!node.IsSequence())
      fail(node, path,
           "expected a list (entries starting with '- '), found " + describe_found(node));
    if (node.size() < spec.min_items)
      fail(node, path,
           "expected at least " + std::to_string(spec.min_items) + " entries, found " +
               std::to_string(node.size()));
    std::map<std::string, int> names;
    for (std::size_t i = 0; i < node.size(); ++i) {
      const std::string item_path = path + "[" + std::to_string(i) + "]";
      out.push_back(check(node[i], *spec.item, item_path));
      if (spec.unique_names && node[i]["name"]) {
        const auto name = node[i]["name"].Scalar();
        auto [it, inserted] = names.emplace(name, node[i]["name"].Mark().line + 1);
        if (!inserted)
          fail(node[i]["name"], item_path + ".name",
               "name '" + name + "' is used twice (first at line " + std::to_string(it->second) +
                   "); names must be unique");
      }
    }
    return out;
  }

  YAML::Node check_map(const YAML::Node& node, const Spec& spec, const std::string& path) {
    if (!node.IsNull() && !node.IsMap())
      fail(node, path,
           "expected a map (indented 'key: value' lines), found " + describe_found(node));

    // Keys as written, with duplicate detection (yaml-cpp silently keeps one of them).
    std::map<std::string, YAML::Node> given_values;
    std::map<std::string, YAML::Node> given_keys;
    std::vector<std::string> order;
    if (node.IsMap()) {
      for (const auto& kv : node) {
        if (!kv.first.IsScalar()) fail(kv.first, path, "keys must be plain names");
        const auto& k = kv.first.Scalar();
        if (given_keys.count(k))
          fail(kv.first, child_path(path, k),
               "duplicate key (first given at line " +
                   std::to_string(given_keys[k].Mark().line + 1) + ")");
        given_keys[k] = kv.first;
        given_values[k] = kv.second;
        order.push_back(k);
      }
    }

    std::vector<Key> allowed = spec.keys;
    std::string variant;
    if (!spec.discriminator.empty()) {
      const Key* disc = nullptr;
      for (const auto& k : spec.keys)
        if (k.name == spec.discriminator) disc = &k;
      if (given_values.count(spec.discriminator)) {
        const auto& dn = given_values[spec.discriminator];
        check(dn, *disc->spec, child_path(path, spec.discriminator));
        variant = dn.Scalar();
      } else if (disc && !disc->default_value.empty()) {
        variant = disc->default_value;
      }
      if (spec.variants.count(variant))
        allowed.insert(allowed.end(), spec.variants.at(variant).begin(),
                       spec.variants.at(variant).end());
    }

    std::vector<std::string> allowed_names;
    for (const auto& k : allowed) allowed_names.push_back(k.name);
    for (const auto& k : order) {
      if (std::find(allowed_names.begin(), allowed_names.end(), k) != allowed_names.end()) continue;
      for (const auto& [other, keys] : spec.variants)
        for (const auto& vk : keys)
          if (vk.name == k)
            fail(given_keys[k], child_path(path, k),
                 "key not allowed with " + spec.discriminator + " '" + variant +
                     "' (it belongs to " + spec.discriminator + " '" + other + "')");
      std::string message = "unknown key '" + k + "'";
      if (auto s = closest_match(k, allowed_names)) message += " (did you mean '" + *s + "'?)";
      message += "; allowed keys here: " + join(allowed_names);
      fail(given_keys[k], child_path(path, k), message);
    }

    for (const auto& group : spec.exactly_one_of) {
      std::vector<std::string> present;
      for (const auto& g : group)
        if (given_values.count(g)) present.push_back(g);
      if (present.size() != 1)
        fail(node, path,
             "expected exactly one of " + join(group, ", ") + ", found " +
                 (present.empty() ? "none" : join(present, " and ")));
    }
    for (const auto& group : spec.at_least_one_of) {
      bool any = false;
      for (const auto& g : group) any = any || given_values.count(g) > 0;
      if (!any) fail(node, path, "expected at least one of " + join(group, ", "));
    }

    YAML::Node out(YAML::NodeType::Map);
    for (const auto& k : allowed) {
      const auto kp = child_path(path, k.name);
      if (given_values.count(k.name)) {
        out[k.name] = check(given_values[k.name], *k.spec, kp);
      } else if (k.required) {
        fail(node, path,
             "missing required key '" + k.name + "' (" + article(*k.spec) +
                 describe_expected(*k.spec) + ": " + first_sentence(k.spec->doc) + ")");
      } else if (!k.default_value.empty()) {
        out[k.name] = check(YAML::Load(k.default_value), *k.spec, kp);
      }
    }
    return out;
  }

  std::string file_;
  std::map<std::string, double> parameters_;
};

}  // namespace

YAML::Node validate(const YAML::Node& document, const Spec& spec, const std::string& file) {
  Validator v(file);
  const bool has_parameters = document.IsMap() && document["parameters"];
  const auto parameters = v.read_parameters(has_parameters ? document["parameters"] : YAML::Node());
  auto out = v.check(document, spec, "");
  if (has_parameters) out["parameters"] = parameters;
  return out;
}

}  // namespace efg::schema
