#pragma once
// Test helpers for files: a temporary folder that cleans up after itself, and whole-file
// read and write.
#include <string>

namespace rlpos::testing {

// A fresh folder under the system's temp dir, removed with everything in it at scope exit
// (even if a test took away its write permission).
class TempDir {
 public:
  TempDir();
  ~TempDir();
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  const std::string& path() const { return path_; }
  std::string File(const std::string& name) const { return path_ + "/" + name; }

 private:
  std::string path_;
};

std::string ReadFile(const std::string& file);
void WriteFile(const std::string& file, const std::string& text);

}  // namespace rlpos::testing
