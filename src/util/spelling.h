// Suggestions for misspelt names ("did you mean <Radius>?", "did you mean --spp?"): the
// scene schema's elements and attributes and the command-line options share this rule.
#pragma once

#include <string>
#include <vector>

namespace rt {

// The Levenshtein distance (insertions, deletions, substitutions), ignoring case.
size_t edit_distance(const std::string& a, const std::string& b);

// The candidate nearest to `typed`, if it is near enough to be a likely slip: at most one
// edit in three characters of the typed name (at least one), and not `typed` itself.
// Ties go to the earlier candidate. "" when none is near.
std::string closest_name(const std::string& typed, const std::vector<std::string>& candidates);

}  // namespace rt
