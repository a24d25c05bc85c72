// Hostile requests over raw sockets against a running server (in this process): traversal, SQL,
// oversize and malformed requests, tokens, slow and idle clients. Each gets a 4xx (or, for the
// slow ones, its connection closed), the server keeps answering, and the database is unchanged.
#include "coordinator/web/http_server.h"

#include <arpa/inet.h>
#include <gtest/gtest.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <thread>

#include "common/store/artifact_files.h"
#include "tests/coordinator/web/web_fixture.h"
#include "tests/support/wait_for.h"

namespace rlpos::web {
namespace {

constexpr double kPatienceS = 30;  // far above the server's own deadlines below

int Connect(int port) {
  const int fd = socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_port = htons(static_cast<uint16_t>(port));
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  EXPECT_EQ(connect(fd, reinterpret_cast<sockaddr*>(&address), sizeof address), 0);
  return fd;
}

bool SendAll(int fd, const std::string& bytes) {
  std::size_t sent = 0;
  while (sent < bytes.size()) {
    const ssize_t n = send(fd, bytes.data() + sent, bytes.size() - sent, MSG_NOSIGNAL);
    if (n <= 0)
      return false;
    sent += static_cast<std::size_t>(n);
  }
  return true;
}

// Everything the server sends until it closes the connection (or kPatienceS passes).
std::string ReadToEnd(int fd) {
  std::string out;
  const auto deadline = std::chrono::steady_clock::now() +
                        std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                            std::chrono::duration<double>(kPatienceS));
  for (;;) {
    pollfd p{fd, POLLIN, 0};
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
        deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0 || poll(&p, 1, static_cast<int>(left.count())) <= 0)
      return out + "<still open>";
    char buffer[4096];
    const ssize_t n = recv(fd, buffer, sizeof buffer, 0);
    if (n <= 0)
      return out;
    out.append(buffer, static_cast<std::size_t>(n));
  }
}

// The status of the response, 0 when the server closed without one.
int ResponseStatus(const std::string& response) {
  if (response.compare(0, 9, "HTTP/1.1 ") != 0)
    return 0;
  return std::stoi(response.substr(9, 3));
}

std::string BodyOf(const std::string& response) {
  const auto at = response.find("\r\n\r\n");
  return at == std::string::npos ? "" : response.substr(at + 4);
}

class HttpServerTest : public ::testing::Test {
 protected:
  void Start(std::optional<std::string> token = std::nullopt) {
    ServeContext context;
    context.db_file = db_.file();
    context.token = token;
    ServerLimits limits;
    limits.threads = 2;
    limits.max_queued = 4;
    limits.request_deadline_s = 1;
    server_ = std::make_unique<HttpServer>(context, limits);
    port_ = server_->Bind({"127.0.0.1", 0});
    thread_ = std::thread([this] { server_->Run(); });
  }

  ~HttpServerTest() override {
    if (server_) {
      server_->Stop();
      thread_.join();
    }
  }

  std::string Exchange(const std::string& request) {
    const int fd = Connect(port_);
    SendAll(fd, request);
    const std::string response = ReadToEnd(fd);
    close(fd);
    return response;
  }

  std::string Get(const std::string& target, const std::string& headers = "") {
    return Exchange("GET " + target + " HTTP/1.1\r\nHost: 127.0.0.1\r\n" + headers + "\r\n");
  }

  void ExpectStillAnswering() {
    const std::string response = Get("/api/campaigns");
    EXPECT_EQ(ResponseStatus(response), 200) << response;
    EXPECT_NE(BodyOf(response).find(db_.id()), std::string::npos);
  }

  testing::CampaignDb db_;
  std::unique_ptr<HttpServer> server_;
  std::thread thread_;
  int port_ = 0;
};

TEST_F(HttpServerTest, AnswersThePageAndTheApi) {
  Start();
  const std::string page = Get("/");
  EXPECT_EQ(ResponseStatus(page), 200);
  EXPECT_NE(page.find("Content-Security-Policy: default-src 'none'"), std::string::npos);
  EXPECT_NE(page.find("X-Content-Type-Options: nosniff"), std::string::npos);
  ExpectStillAnswering();
}

// An artifact's bytes arrive whole (httplib streams them from the file, in chunks), and whole
// too when a range of them is asked for (Range is not served).
TEST_F(HttpServerTest, AnArtifactIsServedWhole) {
  Start();
  const std::string file = (std::filesystem::path(ArtifactsDirOf(db_.file())) / db_.id() /
                            "train/B/seed1/learning_curve.csv")
                               .string();
  std::string bytes;  // larger than httplib's chunk and our 16 KiB reads, binary
  for (int i = 0; i < 100000; ++i)
    bytes += static_cast<char>((i * 7919) % 256);
  std::ofstream(file, std::ios::binary) << bytes;
  const std::string response = Get("/api/artifacts/1");
  ASSERT_EQ(ResponseStatus(response), 200) << response.substr(0, 300);
  EXPECT_NE(response.find("Content-Length: 100000\r\n"), std::string::npos);
  EXPECT_NE(response.find("Content-Disposition: attachment; filename=\"learning_curve.csv\""),
            std::string::npos);
  EXPECT_TRUE(BodyOf(response) == bytes) << BodyOf(response).size() << " bytes of 100000";
  for (const char* range : {"bytes=70000-70009", "bytes=200000-", "bytes=-10"}) {
    const std::string whole = Get("/api/artifacts/1", std::string("Range: ") + range + "\r\n");
    EXPECT_EQ(ResponseStatus(whole), 200) << range << ": " << whole.substr(0, 300);
    EXPECT_TRUE(BodyOf(whole) == bytes) << range << ": " << BodyOf(whole).size() << " bytes";
  }
  ExpectStillAnswering();
}

// Every method but GET and HEAD gets 405 and the Allow header at once, with a body or without
// (a body-less POST is not read to the end of the connection), and a method httplib does not
// know too.
TEST_F(HttpServerTest, OtherMethodsGet405WithAllow) {
  Start();
  const std::string host = "Host: 127.0.0.1\r\n";
  for (const std::string& request : std::vector<std::string>{
           "POST /api/campaigns HTTP/1.1\r\n" + host + "\r\n",
           "POST /api/campaigns HTTP/1.1\r\n" + host + "Content-Length: 3\r\n\r\nabc",
           "PUT /api/artifacts/1 HTTP/1.1\r\n" + host + "\r\n",
           "DELETE /api/campaigns/" + db_.id() + " HTTP/1.1\r\n" + host + "\r\n",
           "OPTIONS / HTTP/1.1\r\n" + host + "\r\n", "PATCH / HTTP/1.1\r\n" + host + "\r\n",
           "TRACE / HTTP/1.1\r\n" + host + "\r\n", "FOO / HTTP/1.1\r\n" + host + "\r\n"}) {
    const auto started = std::chrono::steady_clock::now();
    const std::string response = Exchange(request);
    EXPECT_EQ(ResponseStatus(response), 405) << request << " -> " << response;
    EXPECT_NE(response.find("Allow: GET, HEAD\r\n"), std::string::npos) << response;
    EXPECT_EQ(BodyOf(response), "{\"error\":\"only GET and HEAD are served\"}\n") << response;
    // Answered at once, not at the request's deadline (1 s here).
    EXPECT_LT(std::chrono::steady_clock::now() - started, std::chrono::milliseconds(900))
        << request;
  }
  EXPECT_EQ(ResponseStatus(Exchange("HEAD /api/campaigns HTTP/1.1\r\n" + host + "\r\n")), 200);
}

TEST_F(HttpServerTest, HostileRequestsGet4xxAndChangeNothing) {
  Start();
  const std::string before = db_.Hash();
  const std::string host = "Host: 127.0.0.1\r\n";
  const std::vector<std::string> hostile = {
      "GET /api/campaigns/..%2f..%2fetc%2fpasswd HTTP/1.1\r\n" + host + "\r\n",
      "GET /api/campaigns/%2e%2e HTTP/1.1\r\n" + host + "\r\n",
      "GET /api/campaigns/%2e%2e/%2e%2e/maps HTTP/1.1\r\n" + host + "\r\n",
      "GET /api/artifacts/..%2f1 HTTP/1.1\r\n" + host + "\r\n",
      "GET /api/campaigns?id=1%27%20OR%20%271%27=%271 HTTP/1.1\r\n" + host + "\r\n",
      "GET /api/campaigns/" + db_.id() +
          "/distributions?metric=n_los%27);DROP%20TABLE%20jobs;-- "
          "HTTP/1.1\r\n" +
          host + "\r\n",
      "GET /" + std::string(10000, 'a') + " HTTP/1.1\r\n" + host + "\r\n",
      "GET /api/campaigns HTTP/1.1\r\n" + host + "X-Big: " + std::string(10000, 'b') + "\r\n\r\n",
      "POST /api/campaigns HTTP/1.1\r\n" + host + "Content-Length: 100000\r\n\r\n" +
          std::string(100000, 'c'),
      "DELETE /api/campaigns/" + db_.id() + " HTTP/1.1\r\n" + host + "\r\n",
      "GARBAGE\r\n\r\n",
      "GET\r\n\r\n",
      "GET / HTTP/9.9\r\n" + host + "\r\n",
      std::string("\x16\x03\x01\x02\x00\x01\x00\x01\xfc\x03\x03", 11) + "\r\n\r\n",
      "GET /api/campaigns HTTP/1.0\r\n\r\n",
      "GET /api/campaigns HTTP/1.1\r\nHost: evil.example\r\n\r\n",
  };
  for (const auto& request : hostile) {
    const std::string response = Exchange(request);
    const int status = ResponseStatus(response);
    EXPECT_TRUE(status >= 400 && status < 500) << request.substr(0, 80) << " -> " << response;
    if (status != 0 && !BodyOf(response).empty()) {
      EXPECT_EQ(BodyOf(response).rfind("{\"error\":", 0), 0u) << response;
    }
    ExpectStillAnswering();
  }
  // More headers than the request may hold: refused or cut off, never served.
  std::string many = "GET /api/campaigns HTTP/1.1\r\n" + host;
  for (int i = 0; i < 2000; ++i)
    many += "X-" + std::to_string(i) + ": " + std::string(40, 'h') + "\r\n";
  const std::string response = Exchange(many + "\r\n");
  EXPECT_NE(ResponseStatus(response), 200) << response.substr(0, 200);
  ExpectStillAnswering();
  EXPECT_EQ(db_.Hash(), before);
}

TEST_F(HttpServerTest, ATokenGuardsEveryRequest) {
  Start("0123456789abcdef0123");
  EXPECT_EQ(ResponseStatus(Get("/api/campaigns")), 401);
  EXPECT_EQ(ResponseStatus(Get("/")), 401);
  EXPECT_EQ(ResponseStatus(Get("/api/campaigns", "Authorization: Bearer 0123456789abcdef0124\r\n")),
            401);
  EXPECT_EQ(ResponseStatus(Get("/api/campaigns", "Authorization: Bearer 0123456789abcdef012\r\n")),
            401);
  EXPECT_EQ(ResponseStatus(Get("/api/campaigns", "Authorization: Bearer 0123456789abcdef0123\r\n")),
            200);
  EXPECT_EQ(ResponseStatus(Get("/?token=0123456789abcdef0123")), 200);
}

TEST_F(HttpServerTest, ASlowClientIsCutOffAndOthersAreServedMeanwhile) {
  Start();
  const int slow = Connect(port_);
  ASSERT_TRUE(SendAll(slow, "GET /api/campaigns HTTP/1.1\r\nHost: 127.0.0.1\r\nX-Slow: "));
  // A byte at a time; the server's deadline for the whole request (1 s) ends it.
  bool closed = false;
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(30);
  while (!closed && std::chrono::steady_clock::now() < give_up) {
    ExpectStillAnswering();
    closed = !SendAll(slow, "a");
    pollfd p{slow, POLLIN, 0};
    if (poll(&p, 1, 100) > 0)
      closed = true;  // the end of the connection, or an error answer just before it
  }
  EXPECT_TRUE(closed) << "the slow client was never cut off";
  close(slow);
  ExpectStillAnswering();
}

TEST_F(HttpServerTest, IdleConnectionsDoNotHoldTheServer) {
  Start();
  // More silent connections than threads and queue together.
  std::vector<int> idle;
  for (int i = 0; i < 10; ++i)
    idle.push_back(Connect(port_));
  // Refused while the queue is full, answered once the deadline has freed it.
  EXPECT_TRUE(rlpos::testing::WaitFor([&] { return ResponseStatus(Get("/api/campaigns")) == 200; },
                                      kPatienceS, 100));
  for (int fd : idle)
    close(fd);
}

}  // namespace
}  // namespace rlpos::web
