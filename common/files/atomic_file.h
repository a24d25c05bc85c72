#pragma once
// Files replaced whole (reports, artifacts): a reader (or a writer that dies half way) never
// sees a half-written file, because each is written under a temporary name in the same folder
// and renamed over the old one.
#include <string>

namespace rlpos {

// Creates `dir` and its parents if missing. Throws std::runtime_error naming `dir` when it
// cannot (a file in the way, no permission).
void CreateReportDir(const std::string& dir);

// Writes `content` to `path` atomically (temp file in the same folder, then rename); the file
// is readable by everyone (0644). Throws std::runtime_error naming `path`.
void WriteFileAtomically(const std::string& path, const std::string& content);

}  // namespace rlpos
