#include "coordinator/scheduling/assignment.h"

#include <algorithm>
#include <deque>

namespace rlpos {
namespace {

int KindRank(JobKind kind) {
  switch (kind) {
    case JobKind::kTrain:
      return 0;
    case JobKind::kPosition:
      return 1;
    case JobKind::kEval:
      return 2;
    case JobKind::kTrack:
      return 3;
  }
  return 4;
}

struct CampaignQueue {
  std::string id;
  int running = 0;
  std::deque<const ReadyJob*> jobs;
};

}  // namespace

std::vector<Assignment> AssignJobs(const std::vector<ReadyJob>& ready,
                                   const std::vector<WorkerSlots>& workers,
                                   const std::map<std::string, int>& running_by_campaign) {
  std::vector<WorkerSlots> pool;
  for (const auto& w : workers) {
    const bool seen =
        std::any_of(pool.begin(), pool.end(), [&](const WorkerSlots& p) { return p.id == w.id; });
    if (!seen)
      pool.push_back(w);  // a worker listed twice counts once, as first listed
  }
  std::sort(pool.begin(), pool.end(),
            [](const WorkerSlots& a, const WorkerSlots& b) { return a.id < b.id; });

  std::vector<CampaignQueue> queues;
  for (const auto& job : ready) {
    auto it = std::find_if(queues.begin(), queues.end(),
                           [&](const CampaignQueue& q) { return q.id == job.campaign_id; });
    if (it == queues.end()) {
      const auto running = running_by_campaign.find(job.campaign_id);
      queues.push_back(
          {job.campaign_id, running == running_by_campaign.end() ? 0 : running->second, {}});
      it = queues.end() - 1;
    }
    it->jobs.push_back(&job);
  }
  for (auto& q : queues) {
    std::stable_sort(q.jobs.begin(), q.jobs.end(), [](const ReadyJob* a, const ReadyJob* b) {
      return KindRank(a->params.kind) < KindRank(b->params.kind);
    });
  }

  std::vector<Assignment> out;
  while (true) {
    auto worker =
        std::max_element(pool.begin(), pool.end(), [](const WorkerSlots& a, const WorkerSlots& b) {
          // max_element keeps the first of equals: the lower id.
          return a.slots - a.busy < b.slots - b.busy;
        });
    if (worker == pool.end() || worker->slots - worker->busy <= 0)
      break;
    CampaignQueue* campaign = nullptr;
    for (auto& q : queues) {
      if (!q.jobs.empty() && (!campaign || q.running < campaign->running))
        campaign = &q;
    }
    if (!campaign)
      break;
    out.push_back({*campaign->jobs.front(), worker->id});
    campaign->jobs.pop_front();
    ++campaign->running;
    ++worker->busy;
  }
  return out;
}

}  // namespace rlpos
