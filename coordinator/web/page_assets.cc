#include "coordinator/web/page_assets.h"

#include <openssl/evp.h>
#include <openssl/sha.h>

#include <stdexcept>

namespace rlpos::web {

// Generated from page/ by embed_page.cmake.
extern const char kPageIndexHtml[];
extern const char kPageAppJs[];
extern const char kPageMapJs[];
extern const char kPageStyleCss[];

namespace {

struct Page {
  std::string html, csp;
};

// "'sha256-<base64>'": the CSP source that admits exactly this inline text.
std::string CspHash(const std::string& text) {
  unsigned char digest[SHA256_DIGEST_LENGTH];
  SHA256(reinterpret_cast<const unsigned char*>(text.data()), text.size(), digest);
  unsigned char encoded[4 * ((SHA256_DIGEST_LENGTH + 2) / 3) + 1];
  EVP_EncodeBlock(encoded, digest, SHA256_DIGEST_LENGTH);
  return "'sha256-" + std::string(reinterpret_cast<char*>(encoded)) + "'";
}

void ReplaceOnce(std::string& text, const std::string& marker, const std::string& with) {
  const auto at = text.find(marker);
  if (at == std::string::npos)
    throw std::logic_error("page/index.html has no " + marker);
  text.replace(at, marker.size(), with);
}

Page BuildPage() {
  // Two inline scripts, each admitted by its hash: map.js first, since app.js draws the page as
  // it finishes loading and then calls into it (top-level names are shared across scripts).
  const std::string map_script = std::string("\n") + kPageMapJs;
  const std::string app_script = std::string("\n") + kPageAppJs;
  const std::string style = std::string("\n") + kPageStyleCss;
  Page page{kPageIndexHtml, ""};
  ReplaceOnce(page.html, "<style></style>", "<style>" + style + "</style>");
  ReplaceOnce(page.html, "<script></script>",
              "<script>" + map_script + "</script>\n<script>" + app_script + "</script>");
  page.csp = "default-src 'none'; script-src " + CspHash(map_script) + " " + CspHash(app_script) +
             "; style-src " + CspHash(style) +
             "; connect-src 'self'; img-src 'self' data: blob:; base-uri 'none'; "
             "form-action 'none'; frame-ancestors 'none'";
  return page;
}

const Page& ThePage() {
  static const Page page = BuildPage();
  return page;
}

}  // namespace

const std::string& PageHtml() {
  return ThePage().html;
}

const std::string& PageContentSecurityPolicy() {
  return ThePage().csp;
}

}  // namespace rlpos::web
