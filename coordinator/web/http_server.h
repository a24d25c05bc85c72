#pragma once
// The campaign page over HTTP: cpp-httplib parses each request and writes each response, but
// the connections are ours. We accept them, run each on a bounded pool of threads, give it a
// deadline for the whole request (a client that sends a byte a second is cut off), a byte limit,
// and one request per connection; when the pool's queue is full, a new connection is closed at
// once. The answers come from Respond (api_router.h).
#include <cstddef>
#include <memory>

#include "coordinator/web/access_control.h"
#include "coordinator/web/api_router.h"

namespace rlpos::web {

struct ServerLimits {
  int threads = 8;                   // requests served at once
  std::size_t max_queued = 64;       // accepted connections waiting for a thread
  double request_deadline_s = 10;    // to receive the whole request
  double response_deadline_s = 300;  // to send the whole response (an artifact may be large)
  std::size_t max_request_bytes = 32 * 1024;  // request line, headers and body together
};

class HttpServer {
 public:
  explicit HttpServer(ServeContext context, ServerLimits limits = {});
  ~HttpServer();
  HttpServer(const HttpServer&) = delete;
  HttpServer& operator=(const HttpServer&) = delete;

  // Listens on the address; returns the port (the one chosen when the address says 0). Throws
  // std::runtime_error naming the address.
  int Bind(const ListenAddress& address);
  // Serves until Stop (from any thread).
  void Run();
  void Stop();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace rlpos::web
