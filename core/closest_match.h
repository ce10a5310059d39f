// "Did you mean" for names a user typed: the renderer's (a shader's constants) and the
// harness's (case keys, lanes, presets) share one rule for what counts as a typo.
#pragma once

#include <string>
#include <vector>

namespace taa {

// Levenshtein distance.
int editDistance(const std::string& a, const std::string& b);

// The candidate nearest to `key`, or "" when none is plausibly a typo of it.
std::string closestMatch(const std::string& key, const std::vector<std::string>& candidates);

}  // namespace taa
