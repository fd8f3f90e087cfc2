#include "scene/ParameterListFromYaml.hpp"

#include <Teuchos_Array.hpp>

#include "core/Errors.hpp"
#include "scene/SchemaValidator.hpp"

namespace efg {
namespace {

void set_scalar(Teuchos::ParameterList& list, const std::string& key, const YAML::Node& value) {
  const auto& text = value.Scalar();
  const bool quoted = value.Tag() == "!";
  bool b = false;
  long long i = 0;
  double d = 0;
  if (!quoted && (text == "true" || text == "false") && YAML::convert<bool>::decode(value, b)) {
    list.set(key, b);
  } else if (!quoted && YAML::convert<long long>::decode(value, i) && i >= INT32_MIN &&
             i <= INT32_MAX) {
    list.set(key, static_cast<int>(i));
  } else if (!quoted && YAML::convert<double>::decode(value, d)) {
    list.set(key, d);
  } else {
    list.set(key, text);
  }
}

void fill(Teuchos::ParameterList& list, const YAML::Node& map, const std::string& file,
          const std::string& path) {
  for (const auto& kv : map) {
    const auto key = kv.first.as<std::string>();
    const auto& value = kv.second;
    const auto key_path = path + "." + key;
    if (value.IsMap()) {
      fill(list.sublist(key), value, file, key_path);
    } else if (value.IsScalar()) {
      set_scalar(list, key, value);
    } else if (value.IsSequence()) {
      Teuchos::Array<double> numbers;
      Teuchos::Array<std::string> words;
      for (const auto& item : value) {
        if (!item.IsScalar())
          throw InputError(
              schema::located_message(file, item, key_path, "expected a list of numbers or words"));
        double d = 0;
        if (YAML::convert<double>::decode(item, d)) numbers.push_back(d);
        words.push_back(item.Scalar());
      }
      if (numbers.size() == words.size())
        list.set(key, numbers);
      else
        list.set(key, words);
    } else {
      throw InputError(
          schema::located_message(file, value, key_path, "expected a value, found nothing"));
    }
  }
}

}  // namespace

Teuchos::ParameterList parameter_list_from_yaml(const YAML::Node& map, const std::string& name,
                                                const std::string& file, const std::string& path) {
  Teuchos::ParameterList list(name);
  if (map && map.IsMap()) fill(list, map, file, path);
  return list;
}

}  // namespace efg
