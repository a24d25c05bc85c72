#include "dds_test_support.h"

#include <unistd.h>

#include <atomic>
#include <cstdio>
#include <filesystem>
#include <string>

#include "dds/participant.h"
#include "process/stop_signal.h"

namespace rlpos::testing {

DdsOptions TestOptions() {
  static std::atomic<int> counter{0};
  const long pid = static_cast<long>(::getpid());
  DdsOptions options;
  options.domain = static_cast<int>(1 + pid % 200);
  options.loopback_tag = "rlpos-test-" + std::to_string(pid) + "-" + std::to_string(++counter);
  return options;
}

std::string SelfExecutable() {
  return std::filesystem::read_symlink("/proc/self/exe").string();
}

int RunChildWriter(int argc, char** argv) {
  if (argc != 5) {
    std::fprintf(stderr, "usage: %s %s DOMAIN TAG WORKER_ID\n", argv[0], kChildWriterFlag);
    return 2;
  }
  InstallStopSignalHandlers();
  try {
    DdsOptions options;
    options.domain = std::stoi(argv[2]);
    options.loopback_tag = argv[3];
    Participant participant(options);
    Writer<msg::WorkerStatus> writer(participant);
    msg::WorkerStatus status;
    status.worker_id = argv[4];
    status.host = "child";
    status.pid = ::getpid();
    status.slots = 3;
    status.busy = 1;
    status.jobs = {"j#1"};
    writer.Write(status);
    std::printf("ready\n");
    std::fflush(stdout);
    for (int i = 0; i < 6000 && !StopRequested(); ++i)
      ::usleep(10000);
    if (!StopRequested())
      return 3;
    writer.Dispose(status);
    std::printf("disposed\n");
    std::fflush(stdout);
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "child writer: %s\n", e.what());
    return 1;
  }
}

}  // namespace rlpos::testing
