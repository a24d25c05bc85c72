#include "coordinator/cli/campaign_client.h"

#include <unistd.h>

#include <chrono>
#include <random>
#include <thread>

#include "common/process/host_name.h"
#include "idl/dds/message_checks.h"
#include "idl/dds/topics.h"
#include "idl/dds/wait_set.h"

namespace rlpos {
namespace {

std::string NewRequestId() {
  std::random_device random;
  return HostName() + "-" + std::to_string(getpid()) + "-" + std::to_string(random());
}

}  // namespace

msg::CampaignRequest SubmitRequest(const CampaignSubmission& submission, bool use_cache) {
  msg::CampaignRequest request;
  request.kind = msg::RequestKind::kSubmit;
  request.no_cache = !use_cache;
  request.campaign_json = submission.campaign_json;
  request.scenarios = submission.scenarios;
  request.policies = submission.policies;
  return request;
}

std::string DescribeDds(const DdsOptions& options) {
  std::string text = "DDS domain " + std::to_string(options.domain);
  if (!options.loopback_tag.empty())
    text += ", loopback tag " + options.loopback_tag;
  return text;
}

msg::CampaignReply SendCampaignRequest(const DdsOptions& dds, msg::CampaignRequest request,
                                       double timeout_s, const std::function<void()>& while_waiting,
                                       const ReplyCheck& check) {
  using Clock = std::chrono::steady_clock;
  const auto deadline = Clock::now() + std::chrono::duration_cast<Clock::duration>(
                                           std::chrono::duration<double>(timeout_s));
  const auto no_answer = [&] {
    return NoCoordinatorError("no coordinator answered on " + DescribeDds(dds) + " within " +
                              std::to_string(static_cast<int>(timeout_s)) +
                              " s (is rlpos-coordinator running there?)");
  };
  Participant participant(dds);
  Reader<msg::CampaignReply> replies(participant);
  Writer<msg::CampaignRequest> requests(participant);
  WaitSet wait_set(participant);
  wait_set.Attach(replies.handle());
  // The request topic is volatile: write only once the coordinator's reader is matched, and
  // its reply writer matched to us, or the request or its answer would be lost.
  while (requests.MatchedReaders() == 0 || replies.MatchedWriters() == 0) {
    if (Clock::now() >= deadline)
      throw no_answer();
    if (while_waiting)
      while_waiting();
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  request.request_id = NewRequestId();
  requests.Write(request);
  // Any participant may match first (an unsecured domain may hold others than the coordinator):
  // when a reader of requests or a writer of replies matches after the write, the coordinator's
  // may be among them and have missed it, so the request goes again (same id; the coordinator's
  // requests are idempotent). Bounded by the participants that join while we wait.
  int readers = requests.MatchedReaders();
  int writers = replies.MatchedWriters();
  std::string refused;  // why the first reply that `check` refused was refused
  while (Clock::now() < deadline) {
    const double left = std::chrono::duration<double>(deadline - Clock::now()).count();
    wait_set.Wait(std::max(0.0, std::min(left, 0.1)));
    if (while_waiting)
      while_waiting();
    const int now_readers = requests.MatchedReaders();
    const int now_writers = replies.MatchedWriters();
    if (now_readers > readers || now_writers > writers)
      requests.Write(request);
    readers = std::max(readers, now_readers);
    writers = std::max(writers, now_writers);
    for (const auto& r : replies.Take()) {
      if (!r.valid || !r.decode_error.empty() ||
          !CheckCampaignReply(r.data, request.request_id).empty())
        continue;
      const std::string problem = check ? check(r.data) : "";
      if (problem.empty())
        return r.data;
      if (refused.empty())
        refused = problem;
    }
  }
  if (!refused.empty())
    throw std::runtime_error(refused);
  throw no_answer();
}

}  // namespace rlpos
