#include "tests/idl/dds/dds_test_support.h"

#include <unistd.h>

#include <atomic>
#include <cstdio>
#include <filesystem>
#include <string>

#include "common/process/stop_signal.h"
#include "idl/dds/participant.h"

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

namespace {

// A child mode's DOMAIN and TAG (argv[2], argv[3]).
DdsOptions ChildOptions(char** argv) {
  DdsOptions options;
  options.domain = std::stoi(argv[2]);
  options.loopback_tag = argv[3];
  return options;
}

}  // namespace

int RunChildWriter(int argc, char** argv) {
  if (argc != 5) {
    std::fprintf(stderr, "usage: %s %s DOMAIN TAG WORKER_ID\n", argv[0], kChildWriterFlag);
    return 2;
  }
  InstallStopSignalHandlers();
  try {
    Participant participant(ChildOptions(argv));
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

int RunChildReader(int argc, char** argv) {
  if (argc != 5) {
    std::fprintf(stderr, "usage: %s %s DOMAIN TAG WORKER_ID\n", argv[0], kChildReaderFlag);
    return 2;
  }
  try {
    Participant participant(ChildOptions(argv));
    Reader<msg::WorkerStatus> reader(participant);
    std::printf("ready\n");
    std::fflush(stdout);
    const std::string worker_id = argv[4];
    if (!AwaitSample(
            reader, [&](const auto& r) { return r.valid && r.data.worker_id == worker_id; }, 30.0))
      return 3;
    std::printf("heard\n");
    std::fflush(stdout);
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "child reader: %s\n", e.what());
    return 1;
  }
}

int RunChildLateCoordinator(int argc, char** argv) {
  if (argc != 4) {
    std::fprintf(stderr, "usage: %s %s DOMAIN TAG\n", argv[0], kChildLateCoordinatorFlag);
    return 2;
  }
  try {
    Participant participant(ChildOptions(argv));
    Reader<msg::CampaignRequest> overheard(participant);
    Writer<msg::CampaignReply> forger(participant);
    std::printf("ready\n");
    std::fflush(stdout);
    const auto first = AwaitSample(
        overheard, [](const Received<msg::CampaignRequest>& r) { return r.valid; }, 30.0);
    if (!first)
      return 3;
    const auto answer = [](Writer<msg::CampaignReply>& writer, const std::string& request_id,
                           const std::string& campaign_id, int jobs) {
      msg::CampaignReply reply;
      reply.request_id = request_id;
      reply.ok = true;
      reply.campaign_id = campaign_id;
      reply.jobs = jobs;
      writer.Write(reply);
    };
    answer(forger, first->data.request_id, "forged000000", 1);
    // The "coordinator" matches only now, after the request was written.
    Reader<msg::CampaignRequest> requests(participant);
    Writer<msg::CampaignReply> replies(participant);
    const auto heard = AwaitSample(
        requests,
        [&](const Received<msg::CampaignRequest>& r) {
          return r.valid && r.data.request_id == first->data.request_id;
        },
        30.0);
    if (!heard)
      return 3;
    answer(replies, heard->data.request_id, "0123456789ab", 3);
    std::printf("answered\n");
    std::fflush(stdout);
    // Until the client has gone (its reader unmatched): a deleted writer could drop the reply.
    return WaitFor([&] { return replies.MatchedReaders() == 0; }, 30.0) ? 0 : 3;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "child late coordinator: %s\n", e.what());
    return 1;
  }
}

}  // namespace rlpos::testing
