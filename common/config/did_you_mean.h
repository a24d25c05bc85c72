#pragma once
#include <string>
#include <vector>

namespace rlpos {

// Edit distance (Levenshtein), case-insensitive.
std::size_t EditDistance(const std::string& a, const std::string& b);

// The closest candidate to `word` if it is plausibly a typo of it, else "".
std::string ClosestMatch(const std::string& word, const std::vector<std::string>& candidates);

}  // namespace rlpos
