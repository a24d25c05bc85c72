#pragma once
// JSON text from the network, parsed within bounds: nlohmann's parser and printer recurse per
// nesting level, so a hostile "[[[[..." would exhaust the stack before any schema check ran.
#include <cstddef>
#include <nlohmann/json.hpp>
#include <string>

namespace rlpos::wire {

// Throws std::invalid_argument naming `what` when the text is longer than `max_bytes`, nests
// deeper than kMaxJsonDepth, or is not JSON.
nlohmann::json ParseBoundedJson(const std::string& text, std::size_t max_bytes,
                                const std::string& what);

// The deepest nesting of arrays and objects in `text` (strings skipped).
std::size_t JsonNestingDepth(const std::string& text);

}  // namespace rlpos::wire
