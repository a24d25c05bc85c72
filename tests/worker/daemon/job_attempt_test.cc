#include "worker/daemon/job_attempt.h"

#include <gtest/gtest.h>
#include <signal.h>

#include <cerrno>
#include <chrono>
#include <filesystem>
#include <stdexcept>

#include "common/wire/job_order.h"
#include "common/wire/policy_bundle.h"
#include "tests/support/process_test_support.h"
#include "worker/daemon/sim_command.h"

namespace rlpos {
namespace {

namespace fs = std::filesystem;
using testing::ReadFile;
using testing::WaitFor;
using testing::WriteFile;

// True if `folder` is `root` or inside it, lexically (no "..", no absolute escape).
bool Inside(const std::string& folder, const std::string& root) {
  const fs::path normal = fs::path(folder).lexically_normal();
  const fs::path relative = normal.lexically_relative(root);
  if (relative.empty())
    return false;
  for (const auto& part : relative) {
    if (part == "..")
      return false;
  }
  return true;
}

TEST(AttemptFolder, OneFolderPerJobComponentAndAttempt) {
  EXPECT_EQ(AttemptFolder("/work", "c0ffee/train/B/seed1", 2),
            "/work/c0ffee/train/B/seed1/attempt2");
  EXPECT_EQ(AttemptFolder("/work", "c0ffee/eval/B/rl@seed2/run1", 1),
            "/work/c0ffee/eval/B/rl@seed2/run1/attempt1");
}

TEST(AttemptFolder, UnsafeCharactersBecomeUnderscores) {
  EXPECT_EQ(AttemptFolder("/w", "c1/eval/B x/rl;rm -rf $HOME/run1", 1),
            "/w/c1/eval/B_x/rl_rm_-rf__HOME/run1/attempt1");
  EXPECT_EQ(AttemptFolder("/w", "c1/a\\b\n*?", 3), "/w/c1/a_b___/attempt3");
}

TEST(AttemptFolder, DotDotAndEmptyComponentsCannotEscape) {
  EXPECT_EQ(AttemptFolder("/w", "c1/../../etc", 1), "/w/c1/_../_../etc/attempt1");
  EXPECT_EQ(AttemptFolder("/w", "/etc/passwd", 1), "/w/_/etc/passwd/attempt1");
  EXPECT_EQ(AttemptFolder("/w", "a//./b", 1), "/w/a/_/_./b/attempt1");
  EXPECT_EQ(AttemptFolder("/w", "..", 1), "/w/_../attempt1");
  for (const std::string id : {"..", "../..", "../../../../tmp/x", "/", "//", "./../x",
                               "a/../../..", "...", "", "c/..%2f..", "c/. ./.."}) {
    const std::string folder = AttemptFolder("/srv/rlpos/work", id, 1);
    EXPECT_TRUE(Inside(folder, "/srv/rlpos/work")) << "\"" << id << "\" -> " << folder;
    EXPECT_NE(fs::path(folder).lexically_normal(), fs::path("/srv/rlpos/work")) << id;
  }
}

JobOrder OrderOf(JobKind kind) {
  JobOrder order;
  order.job_id = "c1/x";
  order.campaign_id = "c1";
  order.timeout_s = 60;
  order.params.kind = kind;
  order.params.scenario = "B";
  order.params.train_seed = 7;
  order.params.fidelity = "packet";
  order.params.positioner = "oracle";
  order.params.rng_run = 3;
  if (kind == JobKind::kEval)
    order.placement = Placement{{50, 35.5, 10}};
  return order;
}

TEST(SimCommandLine, OneCommandPerKindFromTypedFieldsOnly) {
  const std::string sim = "/opt/rlpos/bin/rlpos-sim", folder = "/w/c1/x/attempt1";
  EXPECT_EQ(SimCommandLine(OrderOf(JobKind::kTrain), sim, folder),
            (std::vector<std::string>{sim, "train", "--scenario", folder + "/scenario.json",
                                      "--out", folder + "/out", "--json"}));
  EXPECT_EQ(SimCommandLine(OrderOf(JobKind::kPosition), sim, folder),
            (std::vector<std::string>{sim, "position", "--scenario", folder + "/scenario.json",
                                      "--positioner", "oracle", "--json"}));
  EXPECT_EQ(SimCommandLine(OrderOf(JobKind::kEval), sim, folder),
            (std::vector<std::string>{sim, "eval", "--scenario", folder + "/scenario.json",
                                      "--position", "50,35.5,10", "--json", "--no-progress"}));
  JobOrder track = OrderOf(JobKind::kTrack);
  track.params.positioner = "oracle-track";
  track.params.duration_s = 120;
  EXPECT_EQ(SimCommandLine(track, sim, folder),
            (std::vector<std::string>{sim, "track", "--scenario", folder + "/scenario.json",
                                      "--positioner", "oracle-track", "--duration", "120",
                                      "--RngRun", "3", "--fidelity", "packet", "--json"}));
  JobOrder three = OrderOf(JobKind::kEval);
  three.placement = Placement{{1, 2, 3}, {4, 5, 6}, {7, 8, 9.5}};
  EXPECT_EQ(SimCommandLine(three, sim, folder),
            (std::vector<std::string>{sim, "eval", "--scenario", folder + "/scenario.json",
                                      "--position", "1,2,3", "--position", "4,5,6", "--position",
                                      "7,8,9.5", "--json", "--no-progress"}));
}

TEST(SimCommandLine, NoTextOfTheOrderReachesTheCommandLine) {
  JobOrder order = OrderOf(JobKind::kPosition);
  order.params.positioner = "baseline; rm -rf /";
  order.params.fidelity = "$(id)";
  order.params.overrides = {{"name", "$(id)"}};
  for (const auto kind : {JobKind::kTrain, JobKind::kPosition, JobKind::kEval}) {
    order.params.kind = kind;
    for (const auto& arg : SimCommandLine(order, "/bin/sim", "/w")) {
      EXPECT_EQ(arg.find("$("), std::string::npos) << arg;
      EXPECT_EQ(arg.find(';'), std::string::npos) << arg;
    }
  }
  // A track job spells its positioner and fidelity on the command line: one that is none of
  // the known names is refused, never copied.
  order.params.kind = JobKind::kTrack;
  order.params.duration_s = 10;
  EXPECT_THROW(SimCommandLine(order, "/bin/sim", "/w"), std::invalid_argument);
  order.params.positioner = "centroid-track";
  EXPECT_THROW(SimCommandLine(order, "/bin/sim", "/w"), std::invalid_argument);
  order.params.fidelity = "analytic";
  EXPECT_NO_THROW(SimCommandLine(order, "/bin/sim", "/w"));
}

class TailOfLogTest : public ::testing::Test {
 protected:
  std::string Tail(const std::string& text, int lines = 3, std::size_t max_chars = 400) {
    WriteFile(file_, text);
    return TailOfLog(file_, lines, max_chars);
  }
  testing::TempDir dir_;
  std::string file_ = dir_.File("stderr.log");
};

TEST_F(TailOfLogTest, LastNonEmptyLines) {
  EXPECT_EQ(Tail("one\ntwo\n\n   \nthree\nfour\n"), "two | three | four");
  EXPECT_EQ(Tail("one\ntwo\n", 1), "two");
  EXPECT_EQ(Tail("  padded  \n"), "padded");
  EXPECT_EQ(Tail("no newline at the end"), "no newline at the end");
  EXPECT_EQ(Tail(""), "");
  EXPECT_EQ(TailOfLog(dir_.File("missing.log")), "");
}

TEST_F(TailOfLogTest, CarriageReturnRedrawsKeepWhatIsOnScreen) {
  EXPECT_EQ(Tail("start\nepisode 1/10\repisode 2/10\repisode 3/10\n"), "start | episode 3/10");
  // A redraw that ends with '\r' (the next one not written yet).
  EXPECT_EQ(Tail("start\nepisode 1/10\repisode 2/10\r", 1), "episode 2/10");
  EXPECT_EQ(Tail("step 1\rstep 2\r   \r", 1), "step 2");
  // CRLF line ends.
  EXPECT_EQ(Tail("error one\r\nerror two\r\n"), "error one | error two");
}

TEST_F(TailOfLogTest, LongTailKeepsItsEnd) {
  const std::string line = std::string(300, 'a') + std::string(300, 'b');
  const std::string tail = Tail(line + "\n", 3, 100);
  EXPECT_EQ(tail, "..." + std::string(100, 'b'));
}

class JobAttemptTest : public ::testing::Test {
 protected:
  // Polls until the attempt has an outcome; fails the test after `timeout_s`.
  static JobOutcome AwaitOutcome(JobAttempt& attempt, double timeout_s = 5.0) {
    std::optional<JobOutcome> outcome;
    EXPECT_TRUE(WaitFor([&] { return (outcome = attempt.Poll()).has_value(); }, timeout_s));
    return outcome.value_or(JobOutcome{false, "", "<no outcome>", {}});
  }
  // An eval order; the child is a stand-in "rlpos-sim" (Sim) that gets the real command line:
  // $1 eval, $2 --scenario, $3 the scenario file, $4 --position, $5 x,y,z.
  static JobOrder Order(double timeout_s = 60) {
    JobOrder order = OrderOf(JobKind::kEval);
    order.job_id = "c0ffee/eval/B/rl/run1";
    order.campaign_id = "c0ffee";
    order.attempt = 2;
    order.timeout_s = timeout_s;
    return order;
  }
  // A shell script standing in for rlpos-sim.
  std::string Sim(const std::string& body) {
    const std::string file = dir_.File("sim" + std::to_string(++sims_) + ".sh");
    WriteFile(file, "#!/bin/sh\n" + body + "\n");
    fs::permissions(file, fs::perms::owner_all);
    return file;
  }
  std::string Folder() const { return AttemptFolder(Work(), "c0ffee/eval/B/rl/run1", 2); }
  std::string Work() const { return dir_.path() + "/work"; }

  testing::TempDir dir_;
  int sims_ = 0;
  const nlohmann::json scenario_ = {{"name", "B"}, {"ues", {1, 2}}};
};

TEST_F(JobAttemptTest, SuccessReportsTheChildsJson) {
  const std::string sim = Sim("echo '{\"a\": 1}'");
  JobAttempt attempt(Order(), scenario_, Work(), sim);
  EXPECT_EQ(attempt.Key(), "c0ffee/eval/B/rl/run1#2");
  const JobOutcome outcome = AwaitOutcome(attempt);
  EXPECT_TRUE(outcome.succeeded) << outcome.error;
  EXPECT_EQ(outcome.result_json, "{\"a\":1}");
  EXPECT_EQ(outcome.error, "");
  // The attempt's folder keeps the command and the child's output.
  EXPECT_EQ(ReadFile(Folder() + "/command.txt"), sim + "\neval\n--scenario\n" + Folder() +
                                                     "/scenario.json\n--position\n50,35.5,10\n"
                                                     "--json\n--no-progress\n");
  EXPECT_EQ(ReadFile(Folder() + "/stdout.json"), "{\"a\": 1}\n");
}

TEST_F(JobAttemptTest, TheEffectiveScenarioReachesTheChild) {
  JobAttempt attempt(Order(), scenario_, Work(), Sim("cat \"$3\""));
  const JobOutcome outcome = AwaitOutcome(attempt);
  EXPECT_TRUE(outcome.succeeded) << outcome.error;
  EXPECT_EQ(nlohmann::json::parse(outcome.result_json), scenario_);
  EXPECT_EQ(nlohmann::json::parse(ReadFile(Folder() + "/scenario.json")), scenario_);
}

// An order of `kind` on the shipped scenario B with settings and overrides of every sort, as
// a worker gets it after CheckJobOrder.
JobOrder ShippedOrder(JobKind kind) {
  JobOrder order = OrderOf(kind);
  order.job_id = std::string("c1/") + ToString(kind);
  order.scenario_document = ReadFile(std::string(RLPOS_SOURCE_DIR) + "/campaigns/scenarios/b.json");
  order.params.duration_s = 3;
  if (kind == JobKind::kTrain)
    order.params.train_episodes = 25;
  // The job leaves the warm-up to the scenario: the campaign's "set" decides it.
  order.params.overrides = {{"wifi.mode", "adhoc"}, {"simulation.warmup", "0.25"}};
  return order;
}

TEST_F(JobAttemptTest, TheScenarioFileIsTheEffectiveDocumentOfEachKind) {
  for (const auto kind : {JobKind::kTrain, JobKind::kPosition, JobKind::kEval}) {
    SCOPED_TRACE(ToString(kind));
    const JobOrder order = ShippedOrder(kind);
    const CheckedOrder checked = CheckJobOrder(order, 3600);
    JobAttempt attempt(order, checked.scenario, Work(), Sim("cat \"$3\""));
    const JobOutcome outcome = AwaitOutcome(attempt);
    ASSERT_TRUE(outcome.succeeded) << outcome.error;
    const std::string folder = AttemptFolder(Work(), order.job_id, order.attempt);
    const nlohmann::json written = nlohmann::json::parse(ReadFile(folder + "/scenario.json"));
    EXPECT_EQ(nlohmann::json::parse(outcome.result_json), written);  // what the child read
    EXPECT_EQ(written, EffectiveScenarioDocument(nlohmann::json::parse(order.scenario_document),
                                                 order.params));
    const nlohmann::json& simulation = written["simulation"];
    EXPECT_EQ(simulation["duration"], 3);
    EXPECT_EQ(simulation["warmup"], 0.25);
    EXPECT_EQ(written["wifi"]["mode"], "adhoc");
    EXPECT_EQ(written["name"], "B");
    // Only an eval runs the job's RngRun; the others keep the scenario's.
    EXPECT_EQ(simulation["run"], kind == JobKind::kEval ? 3 : 1);
    if (kind == JobKind::kTrain) {
      // Every setting of a train job is in the file, the seed and the fidelity too.
      EXPECT_EQ(written["agent"]["train_episodes"], 25);
      EXPECT_EQ(written["agent"]["seed"], 7);
      EXPECT_EQ(written["env"]["fidelity"], "packet");
    }
  }
}

TEST_F(JobAttemptTest, TheChildGetsTheCommandLineOfItsKind) {
  const std::string argv_file = dir_.File("argv.txt");
  const std::string sim =
      Sim("for a in \"$@\"; do printf '%s\\n' \"$a\"; done > '" + argv_file + "'; echo '{}'");
  for (const auto kind : {JobKind::kTrain, JobKind::kPosition, JobKind::kEval}) {
    SCOPED_TRACE(ToString(kind));
    const JobOrder order = ShippedOrder(kind);
    JobAttempt attempt(order, CheckJobOrder(order, 3600).scenario, Work(), sim);
    ASSERT_TRUE(AwaitOutcome(attempt).succeeded);
    const auto expected =
        SimCommandLine(order, sim, AttemptFolder(Work(), order.job_id, order.attempt));
    std::string lines;
    for (std::size_t i = 1; i < expected.size(); ++i)
      lines += expected[i] + "\n";
    EXPECT_EQ(ReadFile(argv_file), lines);
    EXPECT_EQ(expected[1], ToString(kind));
  }
}

// A named policy's position job: the child flies the policy from the folder the worker unpacked
// it into, named by its hash inside the work folder, never from anything the order names.
TEST_F(JobAttemptTest, ANamedPolicyIsFlownFromTheFolderTheWorkerNamesByItsHash) {
  JobOrder order = ShippedOrder(JobKind::kPosition);
  order.job_id = "c1/position/B/rl+p1";
  order.params.positioner = "rl";
  order.policy = MakePolicyBundle(
      {{"scenario.json", "{}"}, {"result.json", "{}"}, {"policy.pt", std::string("\0weights", 8)}});
  order.params.policy_sha256 = order.policy->sha256;
  const CheckedOrder checked = CheckJobOrder(order, 3600);
  // The child prints the policy.pt it was pointed at.
  JobAttempt attempt(order, checked.scenario, Work(),
                     Sim("[ \"$5\" = rl ] && [ \"$6\" = --policy ] && "
                         "printf '{\"bytes\": %s}' $(wc -c < \"$7/policy.pt\")"));
  const JobOutcome outcome = AwaitOutcome(attempt);
  ASSERT_TRUE(outcome.succeeded) << outcome.error;
  EXPECT_EQ(outcome.result_json, "{\"bytes\":8}");
  const std::string policy_dir = WorkerPoliciesDir(Work()) + "/" + order.policy->sha256;
  EXPECT_EQ(ReadFile(policy_dir + "/policy.pt"), std::string("\0weights", 8));
  const std::string folder = AttemptFolder(Work(), order.job_id, order.attempt);
  EXPECT_EQ(SimCommandLine(order, "sim", folder, policy_dir),
            (std::vector<std::string>{"sim", "position", "--scenario", folder + "/scenario.json",
                                      "--positioner", "rl", "--policy", policy_dir, "--json"}));
}

TEST_F(JobAttemptTest, TrainGetsAnOutFolderInsideItsAttempt) {
  JobOrder order = Order();
  order.params.kind = JobKind::kTrain;
  JobAttempt attempt(order, scenario_, Work(),
                     Sim("test -d \"$(dirname \"$5\")\" && echo \"{\\\"out\\\": \\\"$5\\\"}\""));
  const JobOutcome outcome = AwaitOutcome(attempt);
  ASSERT_TRUE(outcome.succeeded) << outcome.error;
  EXPECT_EQ(nlohmann::json::parse(outcome.result_json)["out"], Folder() + "/out");
}

TEST_F(JobAttemptTest, NonZeroExitGivesTheLastStderrLinesAndTheExitCode) {
  JobAttempt attempt(Order(), scenario_, Work(),
                     Sim("echo progress >&2; echo 'scenario: bad UE' >&2; exit 4"));
  const JobOutcome outcome = AwaitOutcome(attempt);
  EXPECT_FALSE(outcome.succeeded);
  EXPECT_EQ(outcome.result_json, "");
  EXPECT_EQ(outcome.error, "progress | scenario: bad UE [exit code 4]");
}

TEST_F(JobAttemptTest, SilentFailureAndMissingJson) {
  JobAttempt silent(Order(), scenario_, Work() + "/a", Sim("exit 1"));
  EXPECT_EQ(AwaitOutcome(silent).error, "rlpos-sim failed [exit code 1]");
  JobAttempt no_json(Order(), scenario_, Work() + "/b", Sim("echo done"));
  const JobOutcome outcome = AwaitOutcome(no_json);
  EXPECT_FALSE(outcome.succeeded);
  EXPECT_EQ(outcome.error, "rlpos-sim ended well but printed no JSON result");
  JobAttempt killed(Order(), scenario_, Work() + "/c", Sim("echo dying >&2; kill -KILL $$"));
  EXPECT_EQ(AwaitOutcome(killed).error, "dying [signal 9 (Killed)]");
}

TEST_F(JobAttemptTest, MissingBinaryFailsWithTheReason) {
  JobAttempt attempt(Order(), scenario_, Work(), "/nonexistent/rlpos-sim");
  EXPECT_EQ(AwaitOutcome(attempt).error,
            "cannot run /nonexistent/rlpos-sim: No such file or directory [exit code 127]");
}

TEST_F(JobAttemptTest, TimeoutKillsTheChild) {
  const std::string pid_file = dir_.File("child.pid");
  const auto start = std::chrono::steady_clock::now();
  JobAttempt attempt(Order(0.3), scenario_, Work(),
                     Sim("echo $$ > '" + pid_file + "'; exec sleep 30"));
  ASSERT_TRUE(WaitFor([&] { return !ReadFile(pid_file).empty(); }, 5.0));
  const pid_t pid = std::stoi(ReadFile(pid_file));
  if (std::chrono::steady_clock::now() - start < std::chrono::milliseconds(200)) {
    EXPECT_FALSE(attempt.Poll().has_value());  // well before the timeout
  }

  const JobOutcome outcome = AwaitOutcome(attempt, 5.0);
  EXPECT_FALSE(outcome.succeeded);
  EXPECT_EQ(outcome.error, "timed out after 0.3 s");
  EXPECT_GE(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 0.3);
  errno = 0;
  EXPECT_EQ(::kill(pid, 0), -1);  // killed and reaped
  EXPECT_EQ(errno, ESRCH);
  EXPECT_TRUE(testing::LiveProcessesOfGroup(pid).empty());
}

TEST_F(JobAttemptTest, StopKillsTheChildAndProgressLineFollowsIt) {
  const std::string pid_file = dir_.File("child.pid");
  JobAttempt attempt(Order(), scenario_, Work(),
                     Sim("echo $$ > '" + pid_file +
                         "'; printf 'episode 1/9\\repisode 2/9\\r' >&2; exec sleep 30"));
  EXPECT_TRUE(WaitFor([&] { return attempt.ProgressLine() == "episode 2/9"; }, 5.0))
      << attempt.ProgressLine();
  ASSERT_TRUE(WaitFor([&] { return !ReadFile(pid_file).empty(); }, 5.0));
  const pid_t pid = std::stoi(ReadFile(pid_file));
  EXPECT_FALSE(attempt.Poll().has_value());  // within its timeout: runs until stopped
  attempt.Stop();
  errno = 0;
  EXPECT_EQ(::kill(pid, 0), -1);
  EXPECT_EQ(errno, ESRCH);
}

TEST_F(JobAttemptTest, LeftoverFolderIsReplaced) {
  fs::create_directories(Folder());
  WriteFile(Folder() + "/stale.txt", "from an earlier worker");
  JobAttempt attempt(Order(), scenario_, Work(), Sim("echo 1"));
  EXPECT_FALSE(fs::exists(Folder() + "/stale.txt"));
  EXPECT_TRUE(AwaitOutcome(attempt).succeeded);
}

TEST_F(JobAttemptTest, UnusableWorkDirThrows) {
  const std::string file = dir_.File("a-file");
  WriteFile(file, "");
  EXPECT_THROW(JobAttempt(Order(), scenario_, file, Sim("true")), std::runtime_error);
}

}  // namespace
}  // namespace rlpos
