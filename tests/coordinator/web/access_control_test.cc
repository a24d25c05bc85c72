// Who may read the campaign page: listen addresses, loopback, tokens and Host headers.
#include "coordinator/web/access_control.h"

#include <gtest/gtest.h>

#include <fstream>

#include "tests/support/temp_dir.h"

namespace rlpos::web {
namespace {

TEST(ListenAddress, ParsesHostAndPort) {
  const auto v4 = ParseListenAddress("127.0.0.1:8787");
  EXPECT_EQ(v4.host, "127.0.0.1");
  EXPECT_EQ(v4.port, 8787);
  EXPECT_EQ(ParseListenAddress("localhost:0").host, "127.0.0.1");
  const auto v6 = ParseListenAddress("[::1]:80");
  EXPECT_EQ(v6.host, "::1");
  EXPECT_EQ(v6.port, 80);
}

TEST(ListenAddress, RefusesWhatIsNotAnAddress) {
  for (const char* bad : {"", "8787", "127.0.0.1", "127.0.0.1:", "127.0.0.1:x", "127.0.0.1:70000",
                          "example.org:80", "::1:80", "[::1]80", "127.0.0.1:80:80"}) {
    EXPECT_THROW(ParseListenAddress(bad), std::invalid_argument) << bad;
  }
}

TEST(Loopback, OnlyTheLoopbackIs) {
  EXPECT_TRUE(IsLoopback("127.0.0.1"));
  EXPECT_TRUE(IsLoopback("127.255.0.9"));
  EXPECT_TRUE(IsLoopback("::1"));
  EXPECT_FALSE(IsLoopback("0.0.0.0"));
  EXPECT_FALSE(IsLoopback("::"));
  EXPECT_FALSE(IsLoopback("192.168.1.2"));
  EXPECT_FALSE(IsLoopback("128.0.0.1"));
  EXPECT_FALSE(IsLoopback("localhost"));  // numeric only: ParseListenAddress resolves it
}

TEST(Token, ComparesWholeTokens) {
  const std::string token = "0123456789abcdefXYZ";
  EXPECT_TRUE(SameToken(token, token));
  EXPECT_FALSE(SameToken(token + "0", token));
  EXPECT_FALSE(SameToken(token.substr(1), token));
  EXPECT_FALSE(SameToken("1123456789abcdefXYZ", token));
  EXPECT_FALSE(SameToken("", ""));
  EXPECT_EQ(BearerToken("Bearer abc"), "abc");
  EXPECT_EQ(BearerToken("bearer abc"), std::nullopt);
  EXPECT_EQ(BearerToken("Basic abc"), std::nullopt);
  EXPECT_EQ(BearerToken("Bearer "), std::nullopt);
}

TEST(Token, FileHoldsOneSafeToken) {
  testing::TempDir dir;
  const auto write = [&](const std::string& text) {
    std::ofstream(dir.File("token")) << text;
    return dir.File("token");
  };
  EXPECT_EQ(ReadTokenFile(write("  0123456789abcdef-_.~+/=\nsecond line\n")),
            "0123456789abcdef-_.~+/=");
  EXPECT_THROW(ReadTokenFile(write("short\n")), std::invalid_argument);
  EXPECT_THROW(ReadTokenFile(write("0123456789abcdef\"<script>\n")), std::invalid_argument);
  EXPECT_THROW(ReadTokenFile(dir.File("missing")), std::invalid_argument);
  try {
    ReadTokenFile(dir.File("missing"));
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("--token-file"), std::string::npos) << e.what();
  }
}

TEST(HostHeader, NamesTheLoopback) {
  for (const char* ok :
       {"127.0.0.1:8787", "localhost:8787", "localhost", "[::1]:8787", "127.0.0.1"})
    EXPECT_TRUE(IsLoopbackHostHeader(ok)) << ok;
  for (const char* bad : {"", "evil.example:8787", "localhost.evil.example", "10.0.0.1:8787",
                          "[::1", "127.0.0.1.evil:80"})
    EXPECT_FALSE(IsLoopbackHostHeader(bad)) << bad;
}

}  // namespace
}  // namespace rlpos::web
