#include "coordinator/reporting/progress_text.h"

#include <gtest/gtest.h>

namespace rlpos {
namespace {

CampaignProgress Progress(int total, int succeeded, int failed, int cancelled, int running,
                          int ready = 0, int pending = 0) {
  CampaignProgress p;
  p.campaign_id = "c0ffee";
  p.name = "mini";
  p.state = "active";
  p.total = total;
  p.succeeded = succeeded;
  p.failed = failed;
  p.cancelled = cancelled;
  p.running = running;
  p.ready = ready;
  p.pending = pending;
  return p;
}

CampaignTiming StartedAt(double t) {
  CampaignTiming timing;
  timing.created_at = t - 10;
  timing.first_started_at = t;
  return timing;
}

WorkerRecord Worker(const std::string& id, const std::string& state, int slots, int busy) {
  WorkerRecord w;
  w.id = id;
  w.host = "host-" + id;
  w.pid = 100 + slots;
  w.slots = slots;
  w.busy = busy;
  w.state = state;
  return w;
}

bool Contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

TEST(ProgressText, FormatDuration) {
  EXPECT_EQ(FormatDuration(0), "0s");
  EXPECT_EQ(FormatDuration(42), "42s");
  EXPECT_EQ(FormatDuration(42.4), "42s");
  EXPECT_EQ(FormatDuration(59.6), "1m00s");
  EXPECT_EQ(FormatDuration(200), "3m20s");
  EXPECT_EQ(FormatDuration(3599.4), "59m59s");
  EXPECT_EQ(FormatDuration(3720), "1h02m");
  EXPECT_EQ(FormatDuration(36000), "10h00m");
  EXPECT_EQ(FormatDuration(-5), "0s");
}

TEST(ProgressText, EstimateRemainingSecondsFromTheRateSoFar) {
  // 40 of 100 done in 200 s: 60 left at 5 s each.
  const CampaignProgress p = Progress(100, 30, 5, 5, 2, 58);
  const auto eta = EstimateRemainingSeconds(p, StartedAt(1000), 1200);
  ASSERT_TRUE(eta.has_value());
  EXPECT_DOUBLE_EQ(*eta, 300);
  EXPECT_DOUBLE_EQ(*EstimateRemainingSeconds(Progress(10, 1, 0, 0, 1, 8), StartedAt(0), 50), 450);
}

TEST(ProgressText, NoEstimateWithoutData) {
  // Nothing done yet.
  EXPECT_FALSE(EstimateRemainingSeconds(Progress(10, 0, 0, 0, 2, 8), StartedAt(1000), 1200));
  // Everything done.
  EXPECT_FALSE(EstimateRemainingSeconds(Progress(10, 8, 2, 0, 0), StartedAt(1000), 1200));
  // Nothing ever started.
  EXPECT_FALSE(EstimateRemainingSeconds(Progress(10, 0, 0, 1, 0, 9), CampaignTiming{}, 1200));
  // A clock behind the first start.
  EXPECT_FALSE(EstimateRemainingSeconds(Progress(10, 1, 0, 0, 1, 8), StartedAt(1000), 1000));
  EXPECT_FALSE(EstimateRemainingSeconds(Progress(10, 1, 0, 0, 1, 8), StartedAt(1000), 900));
}

TEST(ProgressText, ProgressLine) {
  EXPECT_EQ(ProgressLine(Progress(100, 39, 1, 0, 2, 58), 200.0),
            "[#########...............] 40/100  running 2  failed 1  ETA 3m20s");
  EXPECT_EQ(ProgressLine(Progress(4, 1, 0, 1, 0, 2), std::nullopt, 8),
            "[####....] 2/4  running 0  cancelled 1");
  EXPECT_EQ(ProgressLine(Progress(3, 3, 0, 0, 0), std::nullopt, 6), "[######] 3/3  running 0");
  EXPECT_EQ(ProgressLine(Progress(3, 0, 0, 0, 1, 2), 5.0, 6), "[......] 0/3  running 1  ETA 5s");
  // An empty campaign shows as complete rather than dividing by zero.
  EXPECT_EQ(ProgressLine(Progress(0, 0, 0, 0, 0), std::nullopt, 4), "[####] 0/0  running 0");
}

TEST(ProgressText, IsSettled) {
  EXPECT_TRUE(IsSettled(Progress(5, 3, 1, 1, 0)));
  EXPECT_TRUE(IsSettled(Progress(0, 0, 0, 0, 0)));
  EXPECT_FALSE(IsSettled(Progress(5, 4, 0, 0, 1)));
  EXPECT_FALSE(IsSettled(Progress(5, 4, 0, 0, 0, 1)));
  EXPECT_FALSE(IsSettled(Progress(5, 4, 0, 0, 0, 0, 1)));
}

TEST(ProgressText, FormatStatusWithoutCampaigns) {
  EXPECT_EQ(FormatStatus({}, {}, {}, 0), "no campaigns\nworkers: 0 alive (0/0 slots busy)\n");
}

TEST(ProgressText, FormatStatusShowsCampaignsAndAliveWorkers) {
  CampaignProgress running = Progress(100, 39, 1, 0, 2, 50, 8);
  CampaignProgress done = Progress(4, 3, 1, 0, 0);
  done.cached = 2;
  done.campaign_id = "deadbeef";
  done.name = "paper";
  done.state = "finished";
  const std::vector<WorkerRecord> workers{Worker("w1", "alive", 2, 1), Worker("w2", "alive", 4, 4),
                                          Worker("w3", "lost", 8, 0),
                                          Worker("w4", "stopped", 1, 0)};
  const std::string text =
      FormatStatus({running, done}, {StartedAt(1000), StartedAt(1000)}, workers, 1200);

  EXPECT_TRUE(Contains(text, "c0ffee  mini  active\n")) << text;
  EXPECT_TRUE(Contains(text,
                       "  jobs: 100 total, 8 pending, 50 ready, 2 running, 39 succeeded, "
                       "1 failed, 0 cancelled\n"))
      << text;
  // 40 done in 200 s, 60 left.
  EXPECT_TRUE(
      Contains(text, "  [#########...............] 40/100  running 2  failed 1  ETA 5m00s\n"))
      << text;
  EXPECT_TRUE(Contains(text, "deadbeef  paper  finished\n")) << text;
  EXPECT_TRUE(Contains(text,
                       "  jobs: 4 total, 0 pending, 0 ready, 0 running, 3 succeeded (2 from "
                       "the cache), 1 failed, 0 cancelled\n"))
      << text;
  // A settled campaign shows no ETA.
  EXPECT_TRUE(Contains(text, "] 4/4  running 0  failed 1\n")) << text;
  EXPECT_TRUE(Contains(text, "workers: 2 alive (5/6 slots busy), 2 gone\n")) << text;
  EXPECT_TRUE(Contains(text, "  w1  host-w1  pid 102  1/2 busy\n")) << text;
  EXPECT_TRUE(Contains(text, "  w2  host-w2  pid 104  4/4 busy\n")) << text;
  EXPECT_FALSE(Contains(text, "w3")) << text;
  EXPECT_FALSE(Contains(text, "w4")) << text;
  // Campaign blocks come in the given order, before the workers.
  EXPECT_LT(text.find("c0ffee"), text.find("deadbeef"));
  EXPECT_LT(text.find("deadbeef"), text.find("workers:"));
}

TEST(ProgressText, FormatStatusWithoutTimingsShowsNoEta) {
  const std::string text = FormatStatus({Progress(10, 5, 0, 0, 1, 4)}, {}, {}, 1200);
  EXPECT_TRUE(Contains(text, "] 5/10  running 1\n")) << text;
  EXPECT_FALSE(Contains(text, "ETA")) << text;
}

}  // namespace
}  // namespace rlpos
