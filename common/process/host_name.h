#pragma once
// This machine's host name: part of worker ids and request ids, and shown by `status`.
#include <string>

namespace rlpos {

std::string HostName();

}  // namespace rlpos
