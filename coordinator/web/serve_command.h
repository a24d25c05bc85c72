#pragma once
// rlpos-campaign serve: the campaign page and its JSON API over the results database, read-only.
#include <string>

namespace rlpos::web {

struct ServeOptions {
  std::string db = "results/rlpos.db";
  std::string listen = "127.0.0.1:8787";  // port 0: any free one (the line printed names it)
  std::string token_file;                 // required for an address other than the loopback
};

// Serves until SIGINT/SIGTERM, then returns. Bad options, an unreadable database or an address
// in use throw (std::invalid_argument, StoreError, std::runtime_error).
void RunServe(const ServeOptions& options);

}  // namespace rlpos::web
