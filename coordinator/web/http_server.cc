#include "coordinator/web/http_server.h"

#include <arpa/inet.h>
#include <fcntl.h>
#include <httplib.h>
#include <malloc.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstring>
#include <deque>
#include <fstream>
#include <mutex>
#include <stdexcept>
#include <thread>
#include <vector>

namespace rlpos::web {
namespace {

using Clock = std::chrono::steady_clock;

Clock::duration ToDuration(double seconds) {
  return std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(seconds));
}

Clock::time_point After(double seconds) {
  return Clock::now() + ToDuration(seconds);
}

// Milliseconds left until `deadline`, at least 0.
int MillisecondsUntil(Clock::time_point deadline) {
  const auto left =
      std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()).count();
  return left > 0 ? static_cast<int>(std::min<long long>(left, 60000)) : 0;
}

bool WaitFor(int fd, short events, Clock::time_point deadline) {
  for (;;) {
    pollfd p{fd, events, 0};
    const int ready = poll(&p, 1, MillisecondsUntil(deadline));
    if (ready > 0)
      return (p.revents & (events | POLLHUP | POLLERR)) != 0;
    if (ready == 0 && Clock::now() >= deadline)
      return false;
    if (ready < 0 && errno != EINTR)
      return false;
  }
}

// Reads and drops what the client still sends (a body refused unread, say a 405's), for half a
// second at most, before the socket is closed: closing with unread bytes resets the connection,
// which may destroy the answer before the client has read it.
void DrainBeforeClose(int fd) {
  const Clock::time_point deadline = After(0.5);
  char buffer[4096];
  std::size_t drained = 0;
  while (drained < (1u << 20) && WaitFor(fd, POLLIN, deadline)) {
    const ssize_t n = recv(fd, buffer, sizeof buffer, MSG_DONTWAIT);
    if (n <= 0)
      return;  // the client's end, or an error
    drained += static_cast<std::size_t>(n);
  }
}

void AddressOf(int fd, bool peer, std::string& ip, int& port) {
  sockaddr_storage address{};
  socklen_t length = sizeof address;
  const int rc = peer ? getpeername(fd, reinterpret_cast<sockaddr*>(&address), &length)
                      : getsockname(fd, reinterpret_cast<sockaddr*>(&address), &length);
  char text[INET6_ADDRSTRLEN] = "";
  port = 0;
  if (rc == 0 && address.ss_family == AF_INET) {
    const auto* v4 = reinterpret_cast<sockaddr_in*>(&address);
    inet_ntop(AF_INET, &v4->sin_addr, text, sizeof text);
    port = ntohs(v4->sin_port);
  } else if (rc == 0 && address.ss_family == AF_INET6) {
    const auto* v6 = reinterpret_cast<sockaddr_in6*>(&address);
    inet_ntop(AF_INET6, &v6->sin6_addr, text, sizeof text);
    port = ntohs(v6->sin6_port);
  }
  ip = text;
}

// A connection with a deadline for the whole request and one for the whole response, and a cap
// on the bytes it may send us: httplib's own timeouts restart with every byte received.
class DeadlineStream : public httplib::Stream {
 public:
  // The deadlines count from the connection's acceptance: time spent queued counts too.
  DeadlineStream(int fd, Clock::time_point accepted, const ServerLimits& limits)
      : fd_(fd),
        read_deadline_(accepted + ToDuration(limits.request_deadline_s)),
        write_deadline_(accepted + ToDuration(limits.response_deadline_s)),
        max_read_(limits.max_request_bytes) {}

  bool is_readable() const override {
    return buffered_ < filled_ || WaitFor(fd_, POLLIN, read_deadline_);
  }
  bool is_writable() const override { return WaitFor(fd_, POLLOUT, write_deadline_); }

  ssize_t read(char* ptr, size_t size) override {
    if (buffered_ == filled_) {
      if (total_read_ >= max_read_ || !WaitFor(fd_, POLLIN, read_deadline_))
        return -1;
      const ssize_t n = recv(fd_, buffer_, std::min(sizeof buffer_, max_read_ - total_read_), 0);
      if (n <= 0)
        return n;
      total_read_ += static_cast<std::size_t>(n);
      buffered_ = 0;
      filled_ = static_cast<std::size_t>(n);
    }
    const std::size_t n = std::min(size, filled_ - buffered_);
    std::memcpy(ptr, buffer_ + buffered_, n);
    buffered_ += n;
    return static_cast<ssize_t>(n);
  }

  ssize_t write(const char* ptr, size_t size) override {
    if (!WaitFor(fd_, POLLOUT, write_deadline_))
      return -1;
    return send(fd_, ptr, size, MSG_NOSIGNAL);
  }

  void get_remote_ip_and_port(std::string& ip, int& port) const override {
    AddressOf(fd_, true, ip, port);
  }
  void get_local_ip_and_port(std::string& ip, int& port) const override {
    AddressOf(fd_, false, ip, port);
  }
  socket_t socket() const override { return fd_; }

 private:
  int fd_;
  Clock::time_point read_deadline_, write_deadline_;
  std::size_t max_read_, total_read_ = 0;
  char buffer_[4096];
  std::size_t buffered_ = 0, filled_ = 0;
};

}  // namespace

// httplib's request parsing and response writing, over a stream we give it. Not in the anonymous
// namespace: HttpServer::Impl holds one.
class RequestProcessor : public httplib::Server {
 public:
  bool Process(httplib::Stream& stream) {
    bool closed = false;
    // A Range request is answered whole, with 200 (RFC 9110 lets a server ignore Range): httplib
    // would send the range of a file under our status 200, and a range past its end on trust.
    return process_request(stream, true, closed, [](httplib::Request& req) { req.ranges.clear(); });
  }
  // httplib writes a streamed body (a content provider's: the artifacts) only while its
  // listening socket is valid, and stops at once when it is not: it never listens here (we
  // accept the connections ourselves), so it is told of our socket, and of the server's stop.
  void SetListening(int fd) { svr_sock_ = fd; }
};

namespace {

const char* ReasonOf(int status) {
  switch (status) {
    case 400:
      return "malformed request";
    case 404:
      return "no such page";
    case 413:
      return "request too large";
    case 414:
      return "URI too long";
    case 416:
      return "bad range";
    default:
      return status >= 500 ? "internal error" : "request refused";
  }
}

httplib::Headers SafetyHeaders() {
  return {{"X-Content-Type-Options", "nosniff"},
          {"Cache-Control", "no-store"},
          {"Referrer-Policy", "no-referrer"},
          {"X-Frame-Options", "DENY"}};
}

// A download name safe in a header: [A-Za-z0-9._-] only.
std::string SafeFileName(const std::string& name) {
  std::string out;
  for (char c : name.substr(0, 100))
    out += (std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '-') ? c : '_';
  return out.empty() ? "artifact" : out;
}

// A method name as a request line has it ("FOO"), which httplib refuses as malformed when it
// does not know it.
bool IsMethodName(const std::string& method) {
  return !method.empty() && method.size() <= 20 &&
         std::all_of(method.begin(), method.end(), [](char c) { return c >= 'A' && c <= 'Z'; });
}

void CopyAnswer(const ApiResponse& answer, httplib::Response& res) {
  res.status = answer.status;
  for (const auto& [name, value] : answer.headers)
    res.set_header(name, value);
  res.set_content(answer.body, answer.content_type);
}

void SendFile(const ApiResponse& answer, httplib::Response& res) {
  auto in = std::make_shared<std::ifstream>(answer.file, std::ios::binary);
  in->seekg(0, std::ios::end);
  const std::streamoff end = in->tellg();
  if (!*in || end < 0) {  // gone since it was resolved
    CopyAnswer(ErrorResponse(404, "the artifact's file cannot be read"), res);
    return;
  }
  const auto size = static_cast<std::size_t>(end);
  in->seekg(0);
  res.set_header("Content-Disposition",
                 "attachment; filename=\"" + SafeFileName(answer.download_name) + "\"");
  res.set_header("Accept-Ranges", "none");  // Process answers a range whole
  res.set_content_provider(size, answer.content_type,
                           [in](std::size_t offset, std::size_t length, httplib::DataSink& sink) {
                             char chunk[16384];
                             in->seekg(static_cast<std::streamoff>(offset));
                             in->read(chunk,
                                      static_cast<std::streamsize>(std::min(length, sizeof chunk)));
                             const auto got = in->gcount();
                             return got > 0 && sink.write(chunk, static_cast<std::size_t>(got));
                           });
}

}  // namespace

struct HttpServer::Impl {
  ServeContext context;
  ServerLimits limits;
  RequestProcessor processor;
  int listen_fd = -1;
  std::atomic<bool> stopping{false};
  std::mutex mutex;
  std::condition_variable ready;
  struct Accepted {
    int fd;
    Clock::time_point at;
  };
  std::deque<Accepted> queue;
  std::vector<std::thread> threads;

  void Handle(const httplib::Request& req, httplib::Response& res) {
    HttpRequestView view;
    view.method = req.method;
    view.path = req.path;
    for (const auto& [name, value] : req.params)
      view.query.emplace_back(name, value);
    view.authorization = req.get_header_value("Authorization");
    view.host = req.get_header_value("Host");
    const ApiResponse answer = Respond(view, context);
    if (answer.file.empty()) {
      CopyAnswer(answer, res);
      return;
    }
    res.status = answer.status;
    for (const auto& [name, value] : answer.headers)
      res.set_header(name, value);
    SendFile(answer, res);
  }

  // httplib's own refusals (a malformed request line, an oversize header or body) get the
  // page's one-line JSON error too. A well-formed request line of a method httplib does not
  // know ("FOO / HTTP/1.1") is refused as every method but GET and HEAD is: 405.
  void FillError(const httplib::Request& req, httplib::Response& res) {
    if (!res.body.empty())
      return;
    if (res.status == 400 && !req.version.empty() && IsMethodName(req.method) &&
        req.method != "GET" && req.method != "HEAD") {
      CopyAnswer(MethodNotAllowed(), res);
      return;
    }
    const ApiResponse answer = ErrorResponse(res.status, ReasonOf(res.status));
    res.set_content(answer.body, answer.content_type);
  }

  void Configure() {
    const auto handler = [this](const httplib::Request& req, httplib::Response& res) {
      Handle(req, res);
    };
    processor.Get(".*", handler);  // and HEAD
    // Every other method is answered before httplib reads a body: a POST without one would
    // have it wait for the end of the connection, and answer 400 at the request's deadline.
    processor.set_pre_routing_handler([this](const httplib::Request& req, httplib::Response& res) {
      if (req.method == "GET" || req.method == "HEAD")
        return httplib::Server::HandlerResponse::Unhandled;
      Handle(req, res);
      return httplib::Server::HandlerResponse::Handled;
    });
    processor.set_payload_max_length(limits.max_request_bytes);
    processor.set_default_headers(SafetyHeaders());
    processor.set_error_handler(
        [this](const httplib::Request& req, httplib::Response& res) { FillError(req, res); });
    processor.set_exception_handler(
        [](const httplib::Request&, httplib::Response& res, std::exception_ptr) {
          const ApiResponse answer = ErrorResponse(500, "internal error");
          res.status = 500;
          res.set_content(answer.body, answer.content_type);
        });
  }

  void Serve(const Accepted& connection) {
    DeadlineStream stream(connection.fd, connection.at, limits);
    processor.Process(stream);
    shutdown(connection.fd, SHUT_WR);
    DrainBeforeClose(connection.fd);
    close(connection.fd);
    // An answer over a large campaign builds megabytes of JSON in this thread's arena: given
    // back, so that the server idles at a few MiB whatever it served.
    malloc_trim(0);
  }

  void WorkerLoop() {
    for (;;) {
      Accepted connection;
      {
        std::unique_lock<std::mutex> lock(mutex);
        ready.wait(lock, [this] { return stopping || !queue.empty(); });
        if (queue.empty())
          return;
        connection = queue.front();
        queue.pop_front();
      }
      Serve(connection);
    }
  }

  void Enqueue(int fd) {
    {
      std::lock_guard<std::mutex> lock(mutex);
      if (queue.size() < limits.max_queued) {
        queue.push_back({fd, Clock::now()});
        ready.notify_one();
        return;
      }
    }
    close(fd);  // too many waiting already: refused rather than held
  }
};

HttpServer::HttpServer(ServeContext context, ServerLimits limits)
    : impl_(std::make_unique<Impl>()) {
  impl_->context = std::move(context);
  impl_->limits = limits;
  impl_->Configure();
}

HttpServer::~HttpServer() {
  Stop();
  for (auto& t : impl_->threads) {
    if (t.joinable())
      t.join();
  }
  for (const auto& connection : impl_->queue)
    close(connection.fd);
  if (impl_->listen_fd >= 0)
    close(impl_->listen_fd);
}

int HttpServer::Bind(const ListenAddress& address) {
  sockaddr_storage storage{};
  socklen_t length = 0;
  auto* v4 = reinterpret_cast<sockaddr_in*>(&storage);
  auto* v6 = reinterpret_cast<sockaddr_in6*>(&storage);
  if (inet_pton(AF_INET, address.host.c_str(), &v4->sin_addr) == 1) {
    v4->sin_family = AF_INET;
    v4->sin_port = htons(static_cast<uint16_t>(address.port));
    length = sizeof *v4;
  } else if (inet_pton(AF_INET6, address.host.c_str(), &v6->sin6_addr) == 1) {
    v6->sin6_family = AF_INET6;
    v6->sin6_port = htons(static_cast<uint16_t>(address.port));
    length = sizeof *v6;
  } else {
    throw std::runtime_error("cannot listen on " + address.host + ": not an IP address");
  }
  const std::string where = address.host + ":" + std::to_string(address.port);
  const int fd = socket(storage.ss_family, SOCK_STREAM | SOCK_CLOEXEC, 0);
  const int on = 1;
  setsockopt(fd, SOL_SOCKET, SO_REUSEADDR, &on, sizeof on);
  if (fd < 0 || bind(fd, reinterpret_cast<sockaddr*>(&storage), length) != 0 ||
      listen(fd, 64) != 0) {
    const std::string reason = std::strerror(errno);
    if (fd >= 0)
      close(fd);
    throw std::runtime_error("cannot listen on " + where + ": " + reason);
  }
  impl_->listen_fd = fd;
  impl_->processor.SetListening(fd);
  std::string ip;
  int port = 0;
  AddressOf(fd, false, ip, port);
  return port;
}

void HttpServer::Run() {
  for (int i = 0; i < impl_->limits.threads; ++i)
    impl_->threads.emplace_back([this] { impl_->WorkerLoop(); });
  while (!impl_->stopping) {
    if (!WaitFor(impl_->listen_fd, POLLIN, After(0.2)))
      continue;
    const int fd = accept4(impl_->listen_fd, nullptr, nullptr, SOCK_CLOEXEC);
    if (fd >= 0)
      impl_->Enqueue(fd);
  }
  impl_->ready.notify_all();
  for (auto& t : impl_->threads)
    t.join();
  impl_->threads.clear();
}

void HttpServer::Stop() {
  impl_->stopping = true;
  impl_->processor.SetListening(INVALID_SOCKET);  // a download under way ends
  impl_->ready.notify_all();
}

}  // namespace rlpos::web
