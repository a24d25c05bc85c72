#include "common/wire/identifiers.h"

namespace rlpos::wire {
namespace {

bool IsNameChar(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '.' ||
         c == '_' || c == '@' || c == '+' || c == '-';
}

}  // namespace

bool IsSafeName(const std::string& text, std::size_t max_length) {
  if (text.empty() || text.size() > max_length || text == "." || text == "..")
    return false;
  for (const char c : text) {
    if (!IsNameChar(c))
      return false;
  }
  return true;
}

bool IsSafePath(const std::string& text, std::size_t max_length) {
  if (text.empty() || text.size() > max_length)
    return false;
  std::size_t begin = 0;
  for (;;) {
    const std::size_t slash = text.find('/', begin);
    const std::string part =
        text.substr(begin, slash == std::string::npos ? std::string::npos : slash - begin);
    if (!IsSafeName(part, max_length))
      return false;
    if (slash == std::string::npos)
      return true;
    begin = slash + 1;
  }
}

std::string Printable(const std::string& text, std::size_t max) {
  std::string out;
  for (const char c : text.substr(0, max)) {
    const auto u = static_cast<unsigned char>(c);
    out += (u >= 0x20 && u < 0x7f) ? c : '?';
  }
  if (text.size() > max)
    out += "...";
  return out;
}

}  // namespace rlpos::wire
