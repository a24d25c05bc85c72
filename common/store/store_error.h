#pragma once
// Every failure of the results store names the database file, e.g.
//   results store results/rlpos.db: schema version 7 is newer than this build knows (1)
#include <stdexcept>
#include <string>

namespace rlpos {

class StoreError : public std::runtime_error {
 public:
  StoreError(const std::string& file, const std::string& problem)
      : std::runtime_error("results store " + file + ": " + problem), file_(file) {}
  const std::string& file() const { return file_; }

 private:
  std::string file_;
};

}  // namespace rlpos
