#pragma once
// Who may read the campaign page: the address it listens on (loopback unless a token guards
// it), the token itself, and the checks of each request (the token, compared in constant time;
// without one, a loopback Host header, so that a web page that rebinds its DNS name to
// 127.0.0.1 cannot read the API from the user's browser).
#include <optional>
#include <string>

namespace rlpos::web {

struct ListenAddress {
  std::string host;  // numeric: "127.0.0.1", "::1", "0.0.0.0"...
  int port = 0;      // 0: any free port
};

// "HOST:PORT", "[V6]:PORT" or "localhost:PORT". Throws std::invalid_argument naming the part.
ListenAddress ParseListenAddress(const std::string& text);
// 127.0.0.0/8 or ::1.
bool IsLoopback(const std::string& numeric_host);

// The token in the file: its first line, trimmed; at least 16 characters of [A-Za-z0-9._~+/=-].
// Throws std::invalid_argument naming the file.
std::string ReadTokenFile(const std::string& file);

// Equal, in a time that does not depend on where they differ.
bool SameToken(const std::string& given, const std::string& expected);

// The token of "Authorization: Bearer <token>", or nullopt.
std::optional<std::string> BearerToken(const std::string& authorization_header);

// A Host header that names the loopback ("127.0.0.1:8787", "localhost:8787", "[::1]:8787").
bool IsLoopbackHostHeader(const std::string& host_header);

}  // namespace rlpos::web
