#include "scene/YamlDocument.hpp"

#include <sstream>

#include "core/Errors.hpp"

namespace efg {
namespace {

// YAML aliases share nodes, so a small file can expand to billions of them ("billion laughs");
// every later pass walks the expanded tree. Counted with an early stop, before anything walks it.
bool larger_than(const YAML::Node& node, std::size_t& budget) {
  if (budget == 0) return true;
  --budget;
  if (node.IsMap()) {
    for (const auto& kv : node)
      if (larger_than(kv.first, budget) || larger_than(kv.second, budget)) return true;
  } else if (node.IsSequence()) {
    for (const auto& item : node)
      if (larger_than(item, budget)) return true;
  }
  return false;
}
constexpr std::size_t kMaxSceneNodes = 1000000;

// The line (1-based) of a document marker ('---' or '...' in column 1) that has scene content
// before it, or 0. YAML::Load reads the first document only and YAML::LoadAll loops forever on
// some malformed text (yaml-cpp issue 1040, a stray ','), so the text is scanned instead.
int second_document_line(const std::string& text) {
  std::istringstream in(text);
  std::string line;
  bool content = false;
  int marker_after_content = 0;
  for (int number = 1; std::getline(in, line); ++number) {
    const bool marker = (line.rfind("---", 0) == 0 || line.rfind("...", 0) == 0) &&
                        (line.size() == 3 || line[3] == ' ' || line[3] == '\t' || line[3] == '\r');
    const auto first = line.find_first_not_of(" \t\r");
    const bool has_text = first != std::string::npos && line[first] != '#' && line[first] != '%';
    if (marker) {
      if (content && !marker_after_content) marker_after_content = number;
      if (line.size() > 4 && line.find_first_not_of(" \t\r", 3) != std::string::npos &&
          marker_after_content)
        return marker_after_content;  // '--- value' after the scene
    } else if (has_text) {
      if (marker_after_content) return marker_after_content;
      content = true;
    }
  }
  return 0;
}

}  // namespace

YAML::Node load_single_document(const std::string& text, const std::string& file) {
  YAML::Node document;
  try {
    if (const int line = second_document_line(text))
      throw InputError(file + ":" + std::to_string(line) +
                       ": (top level): a second YAML document (after '---' or '...'); expected "
                       "one scene per file");
    document = YAML::Load(text);
  } catch (const YAML::ParserException& e) {
    throw InputError(file + ":" + std::to_string(e.mark.line + 1) + ":" +
                     std::to_string(e.mark.column + 1) + ": YAML syntax error: " + e.msg);
  }
  std::size_t budget = kMaxSceneNodes;
  if (larger_than(document, budget))
    throw InputError(file + ": the scene expands to more than " + std::to_string(kMaxSceneNodes) +
                     " YAML nodes (through aliases '*name'?); expected a scene of plain values");
  return document;
}

}  // namespace efg
