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
  // An error about the file itself (it cannot be opened), at no JSON path: described as the
  // problem alone, so that the callers' "<file>: " prefix makes
  //   d.json: cannot open: No such file or directory
  static ConfigError AboutFile(const std::string& problem) {
    ConfigError error("", problem);
    error.about_file_ = true;
    return error;
  }
  const std::string& path() const { return path_; }
  const std::string& problem() const { return problem_; }
  // "<path>: <problem>", the one line users see (prefixed with the file name by callers).
  std::string describe() const {
    if (about_file_)
      return problem_;
    return (path_.empty() ? std::string("/") : path_) + ": " + problem_;
  }

 private:
  std::string path_;
  std::string problem_;
  bool about_file_ = false;
};

}  // namespace rlpos
