#include "coordinator/web/serve_command.h"

#include <chrono>
#include <iostream>
#include <stdexcept>
#include <thread>

#include "common/process/stop_signal.h"
#include "common/store/results_reader.h"
#include "common/store/store_db.h"
#include "coordinator/web/http_server.h"

namespace rlpos::web {
namespace {

// Fails now, with the store's one-line error, rather than on the first request.
void CheckDatabase(const std::string& db) {
  StoreOptions options;
  options.read_only = true;
  StoreDb opened(db, options);
  ResultsReader(opened).AllProgress();
}

std::string UrlOf(const ListenAddress& address, int port) {
  const bool v6 = address.host.find(':') != std::string::npos;
  return "http://" + (v6 ? "[" + address.host + "]" : address.host) + ":" + std::to_string(port) +
         "/";
}

}  // namespace

void RunServe(const ServeOptions& options) {
  const ListenAddress address = ParseListenAddress(options.listen);
  if (!IsLoopback(address.host) && options.token_file.empty()) {
    throw std::invalid_argument("--listen " + options.listen +
                                " is not a loopback address: give --token-file too");
  }
  ServeContext context;
  context.db_file = options.db;
  if (!options.token_file.empty())
    context.token = ReadTokenFile(options.token_file);
  CheckDatabase(options.db);
  HttpServer server(context);
  const int port = server.Bind(address);
  std::cout << "serving " << options.db << " on " << UrlOf(address, port)
            << (context.token ? " (token required)" : "") << std::endl;
  std::thread serving([&server] { server.Run(); });
  while (!StopRequested())
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  server.Stop();
  serving.join();
}

}  // namespace rlpos::web
