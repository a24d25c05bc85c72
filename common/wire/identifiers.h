#pragma once
// Which names may cross the network. Job ids become folder names on the worker and appear in
// logs, so they hold only [A-Za-z0-9._@+-] and '/' between non-empty components that are not
// "." or "..".
#include <cstddef>
#include <string>

namespace rlpos::wire {

// [A-Za-z0-9._@+-]{1,max_length}, not "." nor "..".
bool IsSafeName(const std::string& text, std::size_t max_length);
// Components as IsSafeName, joined by '/'.
bool IsSafePath(const std::string& text, std::size_t max_length);
// The text with control and non-ASCII bytes replaced by '?', cut to `max` bytes: what a warning
// may quote of a hostile string.
std::string Printable(const std::string& text, std::size_t max = 80);

}  // namespace rlpos::wire
