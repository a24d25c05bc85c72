#pragma once
// A configuration error that names the JSON path and the problem, e.g.
//   scenario.json: /ues/3/position: UE is inside building 2 ("office")
#include <stdexcept>
#include <string>

namespace rlpos {

class ConfigError : public std::runtime_error {
 public:
  ConfigError(std::string path, const std::string& problem)
      : std::runtime_error(problem), path_(std::move(path)), problem_(problem) {}
  const std::string& path() const { return path_; }
  const std::string& problem() const { return problem_; }
  // "<path>: <problem>", the one line users see (prefixed with the file name by callers).
  std::string describe() const {
    return (path_.empty() ? std::string("/") : path_) + ": " + problem_;
  }

 private:
  std::string path_;
  std::string problem_;
};

}  // namespace rlpos
