// "Did you mean" suggestions for misspelt keys and choices.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace efg {

/// Levenshtein edit distance (insertions, deletions, substitutions each cost 1).
std::size_t edit_distance(const std::string& a, const std::string& b);

/// The closest candidate when it is close enough to be a plausible typo: at most 2 edits, or a
/// third of the word's length for long words. Nothing otherwise.
std::optional<std::string> closest_match(const std::string& word,
                                         const std::vector<std::string>& candidates);

}  // namespace efg
