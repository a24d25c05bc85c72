#include "coordinator/web/access_control.h"

#include <arpa/inet.h>
#include <openssl/crypto.h>

#include <cstring>
#include <fstream>
#include <stdexcept>

namespace rlpos::web {
namespace {

int ParsePort(const std::string& text, const std::string& whole) {
  if (text.empty() || text.size() > 5 || text.find_first_not_of("0123456789") != std::string::npos)
    throw std::invalid_argument("--listen " + whole + ": the port is not a number");
  const int port = std::stoi(text);
  if (port > 65535)
    throw std::invalid_argument("--listen " + whole + ": the port is above 65535");
  return port;
}

bool IsNumericHost(const std::string& host) {
  unsigned char buffer[sizeof(in6_addr)];
  return inet_pton(AF_INET, host.c_str(), buffer) == 1 ||
         inet_pton(AF_INET6, host.c_str(), buffer) == 1;
}

// The host part of a Host header: "[::1]:80" -> "::1", "a:80" -> "a", "a" -> "a".
std::string HostOfHeader(const std::string& header) {
  if (!header.empty() && header[0] == '[') {
    const auto end = header.find(']');
    return end == std::string::npos ? "" : header.substr(1, end - 1);
  }
  return header.substr(0, header.find(':'));
}

}  // namespace

ListenAddress ParseListenAddress(const std::string& text) {
  ListenAddress address;
  std::string host, port;
  if (!text.empty() && text[0] == '[') {
    const auto end = text.find("]:");
    if (end == std::string::npos)
      throw std::invalid_argument("--listen " + text + ": expected [IPV6]:PORT");
    host = text.substr(1, end - 1);
    port = text.substr(end + 2);
  } else {
    const auto colon = text.rfind(':');
    if (colon == std::string::npos || text.find(':') != colon)
      throw std::invalid_argument("--listen " + text + ": expected HOST:PORT");
    host = text.substr(0, colon);
    port = text.substr(colon + 1);
  }
  if (host == "localhost")
    host = "127.0.0.1";
  if (!IsNumericHost(host))
    throw std::invalid_argument("--listen " + text +
                                ": the host must be an IP address (or localhost)");
  address.host = host;
  address.port = ParsePort(port, text);
  return address;
}

bool IsLoopback(const std::string& host) {
  in_addr v4{};
  if (inet_pton(AF_INET, host.c_str(), &v4) == 1)
    return (ntohl(v4.s_addr) >> 24) == 127;
  in6_addr v6{};
  return inet_pton(AF_INET6, host.c_str(), &v6) == 1 && IN6_IS_ADDR_LOOPBACK(&v6);
}

std::string ReadTokenFile(const std::string& file) {
  std::ifstream in(file);
  if (!in)
    throw std::invalid_argument("--token-file " + file + ": cannot read");
  std::string token;
  std::getline(in, token);
  const auto first = token.find_first_not_of(" \t\r");
  const auto last = token.find_last_not_of(" \t\r");
  token = first == std::string::npos ? "" : token.substr(first, last - first + 1);
  if (token.size() < 16 || token.size() > 256)
    throw std::invalid_argument("--token-file " + file +
                                ": the token must have 16 to 256 characters");
  if (token.find_first_not_of("ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789"
                              "._~+/=-") != std::string::npos)
    throw std::invalid_argument("--token-file " + file +
                                ": the token may hold only letters, digits and ._~+/=-");
  return token;
}

bool SameToken(const std::string& given, const std::string& expected) {
  // Lengths are compared in the open: the token's length is not the secret, its bytes are.
  if (given.size() != expected.size() || expected.empty())
    return false;
  return CRYPTO_memcmp(given.data(), expected.data(), expected.size()) == 0;
}

std::optional<std::string> BearerToken(const std::string& header) {
  static const std::string kScheme = "Bearer ";
  if (header.size() <= kScheme.size() || header.compare(0, kScheme.size(), kScheme) != 0)
    return std::nullopt;
  return header.substr(kScheme.size());
}

bool IsLoopbackHostHeader(const std::string& header) {
  const std::string host = HostOfHeader(header);
  return host == "localhost" || IsLoopback(host);
}

}  // namespace rlpos::web
