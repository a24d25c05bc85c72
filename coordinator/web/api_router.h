#pragma once
// One HTTP request of the campaign page to its response, with no socket in sight: the access
// check (token or loopback Host), the typed request, the read-only database and the views. The
// HTTP binding (http_server.h) only copies fields in and out, so every answer, the hostile ones
// included, is testable as a function call.
#include <functional>
#include <optional>
#include <string>

#include "coordinator/web/api_request.h"

namespace rlpos::web {

struct HttpRequestView {
  std::string method, path;  // path percent-decoded, without the query
  QueryParams query;
  std::string authorization, host;  // header values, "" when absent
};

struct ApiResponse {
  int status = 200;
  std::string content_type = "application/json";
  std::string body;
  std::string file;           // an artifact: send this file (body empty)
  std::string download_name;  // its name, for Content-Disposition
  std::vector<std::pair<std::string, std::string>> headers;
};

struct ServeContext {
  std::string db_file;
  std::optional<std::string> token;  // every request must carry it when set
  std::function<double()> clock;     // seconds since the epoch; default: the system clock
};

ApiResponse Respond(const HttpRequestView& request, const ServeContext& context);

// {"error": "<message>"} on one line, with the status.
ApiResponse ErrorResponse(int status, const std::string& message);

// 405 with its Allow header: the answer to any method but GET and HEAD.
ApiResponse MethodNotAllowed();

}  // namespace rlpos::web
