#include "daemon/job_attempt.h"

#include <gtest/gtest.h>
#include <signal.h>

#include <cerrno>
#include <chrono>
#include <filesystem>
#include <stdexcept>

#include "process_test_support.h"

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

TEST(BindJobArgv, BindsSimBinaryOutDirAndScenario) {
  JobAttemptSpec spec;
  spec.job_id = "c1/train/B/seed1";
  spec.argv = {"rlpos-sim", "train", "--scenario", "/home/u/b.json", "--seed",
               "1",         "--out", "{out_dir}",  "--json"};
  spec.scenario_document = R"({"name": "B"})";
  EXPECT_EQ(BindJobArgv(spec, "/w/c1/attempt1", "/opt/rlpos/bin/rlpos-sim"),
            (std::vector<std::string>{"/opt/rlpos/bin/rlpos-sim", "train", "--scenario",
                                      "/w/c1/attempt1/scenario.json", "--seed", "1", "--out",
                                      "/w/c1/attempt1/out", "--json"}));
  // Without a document the worker uses the submitter's path as is.
  spec.scenario_document.clear();
  EXPECT_EQ(
      BindJobArgv(spec, "/w/c1/attempt1", "/opt/rlpos/bin/rlpos-sim"),
      (std::vector<std::string>{"/opt/rlpos/bin/rlpos-sim", "train", "--scenario", "/home/u/b.json",
                                "--seed", "1", "--out", "/w/c1/attempt1/out", "--json"}));
}

TEST(BindJobArgv, LeavesOtherProgramsAndArgumentsAlone) {
  JobAttemptSpec spec;
  spec.argv = {"/usr/bin/env", "rlpos-sim", "{position}", "--scenario"};  // trailing flag
  spec.scenario_document = "{}";
  EXPECT_EQ(BindJobArgv(spec, "/f", "/bin/sim"), spec.argv);
  spec.argv.clear();
  EXPECT_TRUE(BindJobArgv(spec, "/f", "/bin/sim").empty());
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
    return outcome.value_or(JobOutcome{false, "", "<no outcome>"});
  }
  static JobAttemptSpec Spec(std::vector<std::string> argv, double timeout_s = 0) {
    JobAttemptSpec spec;
    spec.job_id = "c0ffee/eval/B/rl/run1";
    spec.attempt = 2;
    spec.argv = std::move(argv);
    spec.timeout_s = timeout_s;
    return spec;
  }
  std::string Folder() const { return AttemptFolder(dir_.path(), "c0ffee/eval/B/rl/run1", 2); }

  testing::TempDir dir_;
};

TEST_F(JobAttemptTest, SuccessReportsTheChildsJson) {
  JobAttempt attempt(Spec({"rlpos-sim", "-c", "echo '{\"a\": 1}'"}), dir_.path(), "/bin/sh");
  EXPECT_EQ(attempt.Key(), "c0ffee/eval/B/rl/run1#2");
  const JobOutcome outcome = AwaitOutcome(attempt);
  EXPECT_TRUE(outcome.succeeded) << outcome.error;
  EXPECT_EQ(outcome.result_json, "{\"a\":1}");
  EXPECT_EQ(outcome.error, "");
  // The attempt's folder keeps the command and the child's output.
  EXPECT_EQ(ReadFile(Folder() + "/command.txt"), "/bin/sh\n-c\necho '{\"a\": 1}'\n");
  EXPECT_EQ(ReadFile(Folder() + "/stdout.json"), "{\"a\": 1}\n");
}

TEST_F(JobAttemptTest, ScenarioDocumentAndOutDirReachTheChild) {
  JobAttemptSpec spec = Spec({"rlpos-sim", "-c", "test -d \"$(dirname \"$4\")\" && cat \"$2\"",
                              "sh", "--scenario", "/elsewhere/b.json", "--out", "{out_dir}"});
  spec.scenario_document = R"({"name": "B", "ues": [1, 2]})";
  JobAttempt attempt(spec, dir_.path(), "/bin/sh");
  const JobOutcome outcome = AwaitOutcome(attempt);
  EXPECT_TRUE(outcome.succeeded) << outcome.error;
  EXPECT_EQ(outcome.result_json, R"({"name":"B","ues":[1,2]})");
  EXPECT_EQ(ReadFile(Folder() + "/scenario.json"), spec.scenario_document);
  EXPECT_NE(ReadFile(Folder() + "/command.txt").find("\n" + Folder() + "/out\n"),
            std::string::npos);
}

TEST_F(JobAttemptTest, NonZeroExitGivesTheLastStderrLinesAndTheExitCode) {
  JobAttempt attempt(
      Spec({"rlpos-sim", "-c", "echo progress >&2; echo 'scenario: bad UE' >&2; exit 4"}),
      dir_.path(), "/bin/sh");
  const JobOutcome outcome = AwaitOutcome(attempt);
  EXPECT_FALSE(outcome.succeeded);
  EXPECT_EQ(outcome.result_json, "");
  EXPECT_EQ(outcome.error, "progress | scenario: bad UE [exit code 4]");
}

TEST_F(JobAttemptTest, SilentFailureAndMissingJson) {
  JobAttempt silent(Spec({"rlpos-sim", "-c", "exit 1"}), dir_.path() + "/a", "/bin/sh");
  EXPECT_EQ(AwaitOutcome(silent).error, "rlpos-sim failed [exit code 1]");
  JobAttempt no_json(Spec({"rlpos-sim", "-c", "echo done"}), dir_.path() + "/b", "/bin/sh");
  const JobOutcome outcome = AwaitOutcome(no_json);
  EXPECT_FALSE(outcome.succeeded);
  EXPECT_EQ(outcome.error, "rlpos-sim ended well but printed no JSON result");
  JobAttempt killed(Spec({"rlpos-sim", "-c", "echo dying >&2; kill -KILL $$"}), dir_.path() + "/c",
                    "/bin/sh");
  EXPECT_EQ(AwaitOutcome(killed).error, "dying [signal 9 (Killed)]");
}

TEST_F(JobAttemptTest, MissingBinaryFailsWithTheReason) {
  JobAttempt attempt(Spec({"rlpos-sim", "eval"}), dir_.path(), "/nonexistent/rlpos-sim");
  EXPECT_EQ(AwaitOutcome(attempt).error,
            "cannot run /nonexistent/rlpos-sim: No such file or directory [exit code 127]");
}

TEST_F(JobAttemptTest, TimeoutKillsTheChild) {
  const std::string pid_file = dir_.File("child.pid");
  const auto start = std::chrono::steady_clock::now();
  JobAttempt attempt(Spec({"rlpos-sim", "-c", "echo $$ > \"$0\"; exec sleep 30", pid_file}, 0.3),
                     dir_.path(), "/bin/sh");
  ASSERT_TRUE(WaitFor([&] { return !ReadFile(pid_file).empty(); }, 5.0));
  const pid_t pid = std::stoi(ReadFile(pid_file));
  if (std::chrono::steady_clock::now() - start < std::chrono::milliseconds(200)) {
    EXPECT_FALSE(attempt.Poll().has_value());  // well before the timeout
  }

  const JobOutcome outcome = AwaitOutcome(attempt, 5.0);
  const double took =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_FALSE(outcome.succeeded);
  EXPECT_EQ(outcome.error, "timed out after 0.3 s");
  EXPECT_GE(took, 0.3);
  EXPECT_LT(took, 3.0);
  errno = 0;
  EXPECT_EQ(::kill(pid, 0), -1);  // killed and reaped
  EXPECT_EQ(errno, ESRCH);
  EXPECT_TRUE(testing::LiveProcessesOfGroup(pid).empty());
}

TEST_F(JobAttemptTest, StopKillsTheChildAndProgressLineFollowsIt) {
  const std::string pid_file = dir_.File("child.pid");
  JobAttempt attempt(Spec({"rlpos-sim", "-c",
                           "echo $$ > \"$0\"; printf 'episode 1/9\\repisode 2/9\\r' >&2; "
                           "exec sleep 30",
                           pid_file}),
                     dir_.path(), "/bin/sh");
  EXPECT_TRUE(WaitFor([&] { return attempt.ProgressLine() == "episode 2/9"; }, 5.0))
      << attempt.ProgressLine();
  ASSERT_TRUE(WaitFor([&] { return !ReadFile(pid_file).empty(); }, 5.0));
  const pid_t pid = std::stoi(ReadFile(pid_file));
  EXPECT_FALSE(attempt.Poll().has_value());  // no timeout: runs until stopped
  attempt.Stop();
  errno = 0;
  EXPECT_EQ(::kill(pid, 0), -1);
  EXPECT_EQ(errno, ESRCH);
}

TEST_F(JobAttemptTest, LeftoverFolderIsReplaced) {
  fs::create_directories(Folder());
  WriteFile(Folder() + "/stale.txt", "from an earlier worker");
  JobAttempt attempt(Spec({"rlpos-sim", "-c", "echo 1"}), dir_.path(), "/bin/sh");
  EXPECT_FALSE(fs::exists(Folder() + "/stale.txt"));
  EXPECT_TRUE(AwaitOutcome(attempt).succeeded);
}

TEST_F(JobAttemptTest, UnusableWorkDirThrows) {
  const std::string file = dir_.File("a-file");
  WriteFile(file, "");
  EXPECT_THROW(JobAttempt(Spec({"rlpos-sim", "-c", "true"}), file, "/bin/sh"), std::runtime_error);
}

}  // namespace
}  // namespace rlpos
