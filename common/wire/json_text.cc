#include "common/wire/json_text.h"

#include <stdexcept>

#include "common/wire/limits.h"

namespace rlpos::wire {

std::size_t JsonNestingDepth(const std::string& text) {
  std::size_t depth = 0, deepest = 0;
  bool in_string = false, escaped = false;
  for (const char c : text) {
    if (in_string) {
      if (escaped) {
        escaped = false;
      } else if (c == '\\') {
        escaped = true;
      } else if (c == '"') {
        in_string = false;
      }
      continue;
    }
    if (c == '"') {
      in_string = true;
    } else if (c == '[' || c == '{') {
      if (++depth > deepest)
        deepest = depth;
    } else if ((c == ']' || c == '}') && depth > 0) {
      --depth;
    }
  }
  return deepest;
}

nlohmann::json ParseBoundedJson(const std::string& text, std::size_t max_bytes,
                                const std::string& what) {
  if (text.size() > max_bytes) {
    throw std::invalid_argument(what + " is " + std::to_string(text.size()) + " bytes, more than " +
                                std::to_string(max_bytes));
  }
  if (JsonNestingDepth(text) > kMaxJsonDepth) {
    throw std::invalid_argument(what + " nests deeper than " + std::to_string(kMaxJsonDepth));
  }
  try {
    return nlohmann::json::parse(text);
  } catch (const nlohmann::json::exception& e) {
    throw std::invalid_argument(what + " is not JSON (" + std::string(e.what()) + ")");
  }
}

}  // namespace rlpos::wire
