#pragma once
// SHA-256 (libcrypto) as 64 lowercase hex digits: scenario documents, artifacts, job contents.
#include <string>

namespace rlpos {

std::string Sha256Hex(const std::string& data);

// True for 64 lowercase hex digits.
bool IsSha256Hex(const std::string& text);

}  // namespace rlpos
