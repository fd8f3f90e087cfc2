// A small declarative schema for YAML scene files: every key with its type, default, unit, range
// and meaning. The validator (SchemaValidator) checks files against it and fills defaults; the
// documentation generator (SchemaMarkdown) writes docs/scene.md from the very same description,
// so the documentation cannot drift from what is accepted.
#pragma once

#include <cstddef>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "expressions/Expression.hpp"

namespace efg::schema {

enum class Type {
  map,           ///< fixed keys, optionally with a discriminator choosing extra keys
  list,          ///< a sequence of items that all follow `item`
  real,          ///< a finite floating-point number
  integer,       ///< a whole number
  boolean,       ///< true or false
  string,        ///< any scalar text
  choice,        ///< one of `choices`
  real_list,     ///< a sequence of reals (or one real when `scalar_allowed`)
  integer_list,  ///< a sequence of integers
  string_list,   ///< a sequence of strings (restricted to `choices` when given)
  passthrough    ///< a free map handed unchecked to a Trilinos package as a ParameterList
};

struct Spec;
using SpecPtr = std::shared_ptr<const Spec>;

struct Key {
  std::string name;
  SpecPtr spec;
  bool required = false;
  std::string default_value;  ///< YAML text of the default; empty means "no default"
};

struct Spec {
  Type type = Type::string;
  std::string doc;
  std::string unit;
  // numbers (also the items of real_list / integer_list)
  std::optional<double> min, max;
  bool min_exclusive = false, max_exclusive = false;
  /// Numbers may always be written as expressions of the scene's parameters; keys that vary in
  /// space (and time) also accept the variables x, y, z (and t): these stay text when resolved.
  ExpressionVariables expression = ExpressionVariables::none;
  // choice, string_list
  std::vector<std::string> choices;
  // real_list, integer_list, string_list, list
  std::size_t min_items = 0, max_items = std::numeric_limits<std::size_t>::max();
  bool scalar_allowed = false;
  // map
  std::vector<Key> keys;
  std::string discriminator;                         ///< name of a choice key in `keys`
  std::map<std::string, std::vector<Key>> variants;  ///< extra keys per discriminator value
  std::vector<std::vector<std::string>> exactly_one_of;
  std::vector<std::vector<std::string>> at_least_one_of;
  // list of maps
  SpecPtr item;
  bool unique_names = false;  ///< items are maps whose "name" keys must differ

  std::string type_name() const;
  std::string range_text() const;  ///< e.g. ">= 1", "in (0, 0.5)", "" when unbounded
};

/// Fluent construction: `real("Young's modulus", "stress").above(0)`.
class Builder {
 public:
  explicit Builder(Type type, std::string doc, std::string unit = "");
  Builder& at_least(double v);
  Builder& above(double v);
  Builder& at_most(double v);
  Builder& below(double v);
  Builder& choices(std::vector<std::string> c);
  Builder& items(std::size_t min, std::size_t max);
  Builder& scalar_allowed();
  Builder& varying(ExpressionVariables variables);
  Builder& key(const std::string& name, SpecPtr spec, bool required,
               std::string default_value = "");
  Builder& required(const std::string& name, SpecPtr spec) { return key(name, spec, true); }
  Builder& optional(const std::string& name, SpecPtr spec, std::string default_value = "") {
    return key(name, spec, false, std::move(default_value));
  }
  Builder& discriminated_by(const std::string& key_name);
  Builder& variant(const std::string& value, std::vector<Key> keys);
  Builder& exactly_one_of(std::vector<std::string> names);
  Builder& at_least_one_of(std::vector<std::string> names);
  Builder& item(SpecPtr spec);
  Builder& unique_names();
  operator SpecPtr() const { return std::make_shared<const Spec>(spec_); }  // NOLINT

 private:
  Spec spec_;
};

Builder map(std::string doc);
Builder list(std::string doc, SpecPtr item);
Builder real(std::string doc, std::string unit);
Builder integer(std::string doc);
Builder boolean(std::string doc);
Builder string(std::string doc);
Builder choice(std::string doc, std::vector<std::string> values);
Builder real_list(std::string doc, std::string unit);
Builder integer_list(std::string doc);
Builder string_list(std::string doc);
Builder passthrough(std::string doc);

Key required_key(const std::string& name, SpecPtr spec);
Key optional_key(const std::string& name, SpecPtr spec, std::string default_value = "");

}  // namespace efg::schema
