#pragma once
// What a request of the campaign page gets instead of an answer: an HTTP status (4xx: the
// request's fault) and a one-line message, sent as {"error": "..."}.
#include <stdexcept>
#include <string>

namespace rlpos::web {

class ApiError : public std::runtime_error {
 public:
  ApiError(int status, const std::string& message) : std::runtime_error(message), status_(status) {}
  int status() const { return status_; }

 private:
  int status_;
};

}  // namespace rlpos::web
