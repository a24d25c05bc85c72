#pragma once
// The campaign page: one HTML file with its script and style inlined (page/index.html,
// page/app.js, page/style.css, built into the program by embed_page.cmake), and the
// Content-Security-Policy that lets only those two run: no other script, style, frame or
// network origin (the page works offline and talks to /api/ only).
#include <string>

namespace rlpos::web {

const std::string& PageHtml();
const std::string& PageContentSecurityPolicy();

}  // namespace rlpos::web
