#pragma once
// The campaign page: one HTML file with its scripts and style inlined (page/index.html,
// page/map.js and page/app.js, page/style.css, built into the program by embed_page.cmake), and
// the Content-Security-Policy that lets only those run: no other script, style, frame or
// network origin (the page works offline and talks to /api/ only).
#include <string>

namespace rlpos::web {

const std::string& PageHtml();
const std::string& PageContentSecurityPolicy();

}  // namespace rlpos::web
