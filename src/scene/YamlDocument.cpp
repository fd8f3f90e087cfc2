#include "scene/YamlDocument.hpp"

#include <cstdio>
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

// The 1-based line and column (in characters) of byte `at`, for the messages below.
std::string text_position(const std::string& text, std::size_t at) {
  int line = 1, column = 1;
  for (std::size_t i = 0; i < at; ++i) {
    const auto c = static_cast<unsigned char>(text[i]);
    if (c == '\n') {
      ++line;
      column = 1;
    } else if ((c & 0xC0) != 0x80) {  // a continuation byte does not start a character
      ++column;
    }
  }
  return std::to_string(line) + ":" + std::to_string(column);
}

// Length of the well-formed UTF-8 sequence starting at `i` (RFC 3629: no overlong forms, no
// surrogates, at most U+10FFFF), or 0.
std::size_t utf8_length(const std::string& text, std::size_t i) {
  const auto byte = [&](std::size_t k) {
    return k < text.size() ? static_cast<unsigned char>(text[k]) : 0u;
  };
  const unsigned c = byte(i);
  const auto tail = [&](std::size_t k) { return (byte(k) & 0xC0u) == 0x80u; };
  if (c < 0x80) return 1;
  if (c >= 0xC2 && c <= 0xDF) return tail(i + 1) ? 2 : 0;
  if (c >= 0xE0 && c <= 0xEF) {
    const unsigned lo = c == 0xE0 ? 0xA0 : 0x80, hi = c == 0xED ? 0x9F : 0xBF;
    return byte(i + 1) >= lo && byte(i + 1) <= hi && tail(i + 2) ? 3 : 0;
  }
  if (c >= 0xF0 && c <= 0xF4) {
    const unsigned lo = c == 0xF0 ? 0x90 : 0x80, hi = c == 0xF4 ? 0x8F : 0xBF;
    return byte(i + 1) >= lo && byte(i + 1) <= hi && tail(i + 2) && tail(i + 3) ? 4 : 0;
  }
  return 0;
}

std::string hex_byte(unsigned char c) {
  char s[8];
  std::snprintf(s, sizeof s, "0x%02X", c);
  return s;
}

// A scene is UTF-8 text. yaml-cpp passes other bytes (latin-1, NUL) into the values unchecked,
// where they end as names and titles in the results; refused at the byte, before parsing.
void require_utf8_text(const std::string& text, const std::string& file) {
  for (std::size_t i = 0; i < text.size();) {
    const auto c = static_cast<unsigned char>(text[i]);
    if (c < 0x20 && c != '\t' && c != '\n' && c != '\r')
      throw InputError(file + ":" + text_position(text, i) + ": control character " + hex_byte(c) +
                       (c == 0 ? " (NUL)" : "") +
                       " in the text; expected a scene of UTF-8 text (a binary file?)");
    const std::size_t n = utf8_length(text, i);
    if (n == 0)
      throw InputError(file + ":" + text_position(text, i) + ": byte " + hex_byte(c) +
                       " is not UTF-8; expected a scene of UTF-8 text (latin-1? save the file "
                       "as UTF-8)");
    i += n;
  }
}

std::string located(const std::string& file, const YAML::Node& node, const std::string& path,
                    const std::string& message) {
  const auto mark = node.Mark();
  return file + ":" + std::to_string(mark.line + 1) + ":" + std::to_string(mark.column + 1) + ": " +
         (path.empty() ? "(top level)" : path) + ": " + message;
}

// Explicit tags ('!!binary', '!!str', '!local') are not read: efg takes every value as text
// or number by its key, so a tag would be silently ignored (or a '!!binary' value taken as
// its base64 text). Escapes in double-quoted strings (backslash 0, or the code point 0) still
// make a NUL after the text check above.
void require_plain_values(const YAML::Node& node, const std::string& path,
                          const std::string& file) {
  const auto& tag = node.Tag();
  if (!tag.empty() && tag != "?" && tag != "!") {
    const std::string core = "tag:yaml.org,2002:";
    const std::string shown = tag.rfind(core, 0) == 0 ? "!!" + tag.substr(core.size()) : tag;
    throw InputError(located(file, node, path,
                             "YAML tag '" + shown +
                                 "' is not read; expected plain values (a scene is UTF-8 text: "
                                 "no binary data, no tags)"));
  }
  if (node.IsScalar() && node.Scalar().find('\0') != std::string::npos)
    throw InputError(located(file, node, path,
                             "a NUL character (an escape \\0 or \\u0000?); expected UTF-8 text "
                             "without NUL"));
  if (node.IsMap()) {
    for (const auto& kv : node) {
      const auto key = kv.first.IsScalar() ? kv.first.Scalar() : std::string("?");
      const auto child = path.empty() ? key : path + "." + key;
      require_plain_values(kv.first, child, file);
      require_plain_values(kv.second, child, file);
    }
  } else if (node.IsSequence()) {
    for (std::size_t i = 0; i < node.size(); ++i)
      require_plain_values(node[i], path + "[" + std::to_string(i) + "]", file);
  }
}

}  // namespace

YAML::Node load_single_document(const std::string& text, const std::string& file) {
  require_utf8_text(text, file);
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
  require_plain_values(document, "", file);
  return document;
}

}  // namespace efg
