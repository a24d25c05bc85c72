// rlpos-campaign's bad inputs as a user meets them: one line naming what and where, the
// documented exit code, nothing on stdout, and nothing written (no database, no report).
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iterator>

#include "common/campaign/campaign_spec.h"
#include "common/campaign/expansion.h"
#include "common/hash/sha256.h"
#include "coordinator/scheduling/coordinator_store.h"
#include "tests/support/command.h"

namespace rlpos::testing {
namespace {

namespace fs = std::filesystem;

class RlposCampaignCli : public ::testing::Test {
 protected:
  void SetUp() override {
    char dir[] = "/tmp/rlpos-campaign-cli-XXXXXX";
    ASSERT_NE(mkdtemp(dir), nullptr);
    dir_ = dir;
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::string Write(const std::string& name, const std::string& text) {
    const std::string path = dir_ + "/" + name;
    std::ofstream(path) << text;
    return path;
  }
  CommandResult Campaign(const std::string& args) {
    return RunCommand("cd " + dir_ + " && " + BuiltBinary("rlpos-campaign") + " " + args);
  }
  // A campaign over the shipped scenario B with `extra` fields.
  std::string CampaignJson(const std::string& extra) {
    return R"({"name": "t", "scenarios": [")" + std::string(RLPOS_SOURCE_DIR) +
           R"(/campaigns/scenarios/b.json"], "rng_runs": [1, 2])" + extra + "}";
  }
  // A campaign over the shipped scenario B with one per-scenario override, `set`.
  std::string CampaignSettingB(const std::string& set) {
    return R"({"name": "t", "scenarios": [{"file": ")" + std::string(RLPOS_SOURCE_DIR) +
           R"(/campaigns/scenarios/b.json", "set": [")" + set + R"("]}], "rng_runs": [1, 1]})";
  }
  void ExpectOneLineError(const CommandResult& r, int exit_code, const std::string& fragment) {
    EXPECT_EQ(r.exit_code, exit_code) << r.err;
    EXPECT_TRUE(r.out.empty()) << "stdout must stay empty on failure: " << r.out;
    EXPECT_NE(r.err.find(fragment), std::string::npos) << "stderr: " << r.err;
    EXPECT_EQ(r.err.find("rlpos-campaign: error: "), 0u) << r.err;
    EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << "one line: " << r.err;
  }
  // Nothing half-written: no database, no logs, no reports.
  void ExpectNothingWritten() { EXPECT_FALSE(fs::exists(dir_ + "/results")) << dir_; }

  // A loopback tag nobody else uses: the request must find no coordinator.
  std::string LonelyDds() {
    return "--loopback rlpos-cli-test-" + std::to_string(getpid()) + " --timeout 1";
  }

  std::string dir_;
};

TEST_F(RlposCampaignCli, MissingCampaignFile) {
  ExpectOneLineError(Campaign("run nowhere.json"), 2,
                     "nowhere.json: cannot open: No such file or directory");
  ExpectNothingWritten();
}

TEST_F(RlposCampaignCli, MalformedJson) {
  const auto file = Write("bad.json", "{\"name\": \"x\",");
  ExpectOneLineError(Campaign("run " + file), 2, "bad.json: /: malformed JSON at line");
  ExpectNothingWritten();
}

TEST_F(RlposCampaignCli, UnknownKeySuggestsTheRightOne) {
  const auto file = Write("k.json", CampaignJson(", \"retris\": 2"));
  ExpectOneLineError(Campaign("run " + file), 2,
                     "k.json: /retris: unknown key \"retris\"; did you mean \"retries\"?");
  ExpectNothingWritten();
}

TEST_F(RlposCampaignCli, OutOfRangeValue) {
  const auto file = Write("r.json", CampaignJson(", \"job_timeout_s\": -5"));
  ExpectOneLineError(Campaign("run " + file), 2, "r.json: /job_timeout_s:");
  ExpectNothingWritten();
}

TEST_F(RlposCampaignCli, BrokenScenarioIsRefusedBeforeAnythingStarts) {
  // A building outside the venue, via the campaign's per-scenario overrides.
  const auto file = Write("s.json", CampaignSettingB("buildings.0.x=[45, 500]"));
  const auto r = Campaign("run " + file);
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("s.json: /scenarios/0"), std::string::npos) << r.err;
  ExpectNothingWritten();
}

TEST_F(RlposCampaignCli, ASetThatContradictsTheCampaignIsRefusedBeforeAnythingStarts) {
  // The campaign trains at analytic fidelity (the default); the scenario's "set" says packet.
  const auto file = Write("f.json", CampaignSettingB("env.fidelity=packet"));
  const std::string both =
      "f.json: /scenarios/0/set/0: \"env.fidelity=packet\" contradicts "
      "/train/fidelity";
  ExpectOneLineError(Campaign("run " + file + " --dry-run"), 2, both);
  ExpectOneLineError(Campaign("run " + file), 2, both);
  ExpectOneLineError(Campaign("submit " + file + " " + LonelyDds()), 2, both);
  ExpectNothingWritten();
}

TEST_F(RlposCampaignCli, SubmitWithNoCoordinator) {
  const auto r =
      Campaign("submit " + std::string(RLPOS_SOURCE_DIR) + "/campaigns/mini.json " + LonelyDds());
  ExpectOneLineError(r, 4, "no coordinator answered on DDS domain 0, loopback tag rlpos-cli-test-");
}

TEST_F(RlposCampaignCli, CancelAndRetryWithNoCoordinator) {
  ExpectOneLineError(Campaign("cancel abc " + LonelyDds()), 4, "no coordinator answered");
  ExpectOneLineError(Campaign("retry abc " + LonelyDds()), 4, "no coordinator answered");
}

TEST_F(RlposCampaignCli, BadDdsOptions) {
  EXPECT_EQ(Campaign("cancel abc --domain 999").exit_code, 2);
  ExpectOneLineError(Campaign("cancel abc --loopback 'a b'"), 2, "--loopback: the tag may hold");
  ExpectOneLineError(Campaign("cancel abc --loopback x --dds-config y"), 2,
                     "--loopback and --dds-config exclude each other");
}

TEST_F(RlposCampaignCli, OffLoopbackNeedsSecurityOrInsecure) {
  const std::string campaign = Write("c.json", CampaignJson(""));
  for (const char* command : {"submit c.json", "cancel abc", "retry abc"}) {
    ExpectOneLineError(Campaign(std::string(command) + " --domain 3"), 2,
                       "DDS off loopback needs --security DIR");
    ExpectOneLineError(Campaign(std::string(command) + " --dds-config file:///nowhere.xml"), 2,
                       "or --insecure");
  }
  ExpectOneLineError(Campaign("cancel abc --loopback t --security s --insecure"), 2,
                     "--insecure and --security exclude each other");
}

TEST_F(RlposCampaignCli, SecurityInitAddWorkerAndTheirBadInputs) {
  const auto init = Campaign("security init sec --days 30");
  ASSERT_EQ(init.exit_code, 0) << init.err;
  EXPECT_NE(init.out.find("keep private/"), std::string::npos) << init.out;
  ExpectOneLineError(Campaign("security init sec"), 2, "sec: already exists");
  const auto add = Campaign("security add-worker sec host-b");
  ASSERT_EQ(add.exit_code, 0) << add.err;
  EXPECT_TRUE(fs::is_regular_file(dir_ + "/sec/identities/host-b/permissions.p7s"));
  ExpectOneLineError(Campaign("security add-worker sec host-b"), 2,
                     "sec/identities/host-b: already exists");
  ExpectOneLineError(Campaign("security add-worker sec ../up"), 2, "identity name \"../up\"");
  ExpectOneLineError(Campaign("security add-client none c"), 2, "none: no such folder");
  EXPECT_FALSE(fs::exists(dir_ + "/none"));

  // The identity is checked before any DDS: the file and the cause, exit 2.
  ExpectOneLineError(Campaign("cancel abc " + LonelyDds() + " --security sec --identity host-b"), 2,
                     "sec/identities/host-b/permissions.p7s: identity \"host-b\" is not "
                     "allowed to publish rlpos_campaign_request");
  ExpectOneLineError(Campaign("cancel abc " + LonelyDds() + " --security nowhere"), 2,
                     "nowhere: no such folder");
  // RLPOS_SECURITY stands for --security.
  const auto env = RunCommand("cd " + dir_ + " && RLPOS_SECURITY=elsewhere " +
                              BuiltBinary("rlpos-campaign") + " cancel abc " + LonelyDds());
  ExpectOneLineError(env, 2, "elsewhere: no such folder");
  // A secured client with no coordinator: the usual "no coordinator answered", exit 4.
  const auto lonely = Campaign("cancel abc " + LonelyDds() + " --security sec");
  EXPECT_EQ(lonely.exit_code, 4) << lonely.err;
}

TEST_F(RlposCampaignCli, DaemonsRefuseABadIdentityOrAnUnsecuredNetwork) {
  ASSERT_EQ(Campaign("security init sec").exit_code, 0);
  const auto daemon = [&](const std::string& name, const std::string& args) {
    return RunCommand("cd " + dir_ + " && " + BuiltBinary(name) + " " + args);
  };
  const auto expect = [](const CommandResult& r, const std::string& prefix,
                         const std::string& fragment) {
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_EQ(r.err.find(prefix + ": error: "), 0u) << r.err;
    EXPECT_NE(r.err.find(fragment), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << "one line: " << r.err;
  };
  const std::string tag = "--loopback rlpos-cli-test-" + std::to_string(getpid());
  expect(daemon("rlpos-worker", tag + " --security sec --identity client"), "rlpos-worker",
         "sec/identities/client/permissions.p7s: identity \"client\" is not allowed to publish "
         "rlpos_worker_status");
  expect(daemon("rlpos-coordinator", "--db db/r.db " + tag + " --security sec --identity worker"),
         "rlpos-coordinator", "is not allowed to publish rlpos_job_assignment");
  expect(daemon("rlpos-coordinator", "--db db/r.db --domain 3"), "rlpos-coordinator",
         "DDS off loopback needs --security DIR");
  expect(daemon("rlpos-worker", "--domain 3"), "rlpos-worker", "or --insecure");
  EXPECT_FALSE(fs::exists(dir_ + "/db/r.db")) << "nothing written before the identity is checked";
}

TEST_F(RlposCampaignCli, ReadCommandsOnAMissingDatabase) {
  ExpectOneLineError(Campaign("status --db none.db"), 2, "results store none.db: cannot open");
  ExpectOneLineError(Campaign("results abc --db none.db"), 2, "results store none.db");
  ExpectOneLineError(Campaign("artifacts abc --db none.db"), 2, "results store none.db");
  EXPECT_FALSE(fs::exists(dir_ + "/none.db"));
}

// serve refuses to start, in one line, before it listens anywhere.
TEST_F(RlposCampaignCli, ServeRefusesBadOptions) {
  ExpectOneLineError(Campaign("serve --db none.db --listen 127.0.0.1:0"), 2,
                     "results store none.db: cannot open");
  ExpectOneLineError(Campaign("serve --db none.db --listen 0.0.0.0:0"), 2,
                     "--listen 0.0.0.0:0 is not a loopback address: give --token-file too");
  ExpectOneLineError(Campaign("serve --db none.db --listen example.org:80"), 2,
                     "the host must be an IP address");
  ExpectOneLineError(Campaign("serve --db none.db --listen 0.0.0.0:0 --token-file none"), 2,
                     "--token-file none: cannot read");
  Write("short", "abc\n");
  ExpectOneLineError(Campaign("serve --db none.db --listen 0.0.0.0:0 --token-file short"), 2,
                     "the token must have 16 to 256 characters");
  EXPECT_FALSE(fs::exists(dir_ + "/none.db"));
}

TEST_F(RlposCampaignCli, RunWithADatabaseThatCannotBeOpened) {
  fs::create_directories(dir_ + "/results/a-folder");
  const auto r = Campaign("run " + std::string(RLPOS_SOURCE_DIR) +
                          "/campaigns/mini.json --db results/a-folder");
  ExpectOneLineError(r, 2, "results store results/a-folder: cannot open");
  EXPECT_FALSE(fs::exists(dir_ + "/results/logs")) << "no daemon may have started";
}

TEST_F(RlposCampaignCli, DryRunPrintsThePlanAndWritesNothing) {
  const auto r =
      Campaign("run " + std::string(RLPOS_SOURCE_DIR) + "/campaigns/paper.json --dry-run");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  // A, B, C x RngRun 1-30 x 9 eval labels, plus 1 train and 3 position jobs per scenario.
  EXPECT_NE(r.out.find("(paper): 822 jobs"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("  B: 1 train, 3 position, 270 eval"), std::string::npos) << r.out;
  ExpectNothingWritten();
}

// A database where the mini campaign's train job of B succeeded with one artifact.
TEST_F(RlposCampaignCli, ArtifactsListExportAndTheirBadInputs) {
  std::string id, job;
  {
    CoordinatorStore store(dir_ + "/r.db");
    const ExpandedCampaign campaign =
        ExpandCampaign(ReadCampaignFile(std::string(RLPOS_SOURCE_DIR) + "/campaigns/mini.json"));
    store.ledger.Submit(campaign);
    id = campaign.id;
    job = id + "/train/B/seed1";
    ASSERT_TRUE(store.ledger.MarkRunning(job, "w1", 0, 1));
    ASSERT_EQ(store.recorder.RecordSuccess(job, 1, {{"position", {50, 50, 30}}}, "w1", nullptr,
                                           {{"policy.pt", Sha256Hex("weights"), "weights"}}),
              JobUpdate::kSucceeded);
  }
  const auto list = Campaign("artifacts " + id + " --db r.db");
  ASSERT_EQ(list.exit_code, 0) << list.err;
  EXPECT_NE(list.out.find("train/B/seed1"), std::string::npos) << list.out;
  EXPECT_NE(list.out.find(Sha256Hex("weights").substr(0, 16)), std::string::npos) << list.out;
  EXPECT_EQ(Campaign("artifacts " + job + " --db r.db").out, list.out);  // by job id

  ExpectOneLineError(Campaign("artifacts nosuch --db r.db"), 2, "no campaign \"nosuch\"");
  fs::create_directories(dir_ + "/taken");
  ExpectOneLineError(Campaign("artifacts " + id + " --db r.db --out taken"), 2,
                     "--out: taken already exists");

  const auto exported = Campaign("artifacts " + id + " --db r.db --out out");
  ASSERT_EQ(exported.exit_code, 0) << exported.err;
  std::ifstream policy(dir_ + "/out/train/B/seed1/policy.pt");
  std::string text((std::istreambuf_iterator<char>(policy)), std::istreambuf_iterator<char>());
  EXPECT_EQ(text, "weights");

  // A file changed on disk is refused, and nothing of the export is left.
  std::ofstream(dir_ + "/r.artifacts/" + job + "/policy.pt") << "tampered";
  ExpectOneLineError(Campaign("artifacts " + id + " --db r.db --out out2"), 1,
                     "does not match the sha256 the database holds");
  EXPECT_FALSE(fs::exists(dir_ + "/out2"));
  EXPECT_FALSE(fs::exists(dir_ + "/out2.partial"));

  // A job without artifacts: listing says so and succeeds; an export of nothing fails.
  const std::string eval = id + "/eval/B/baseline/run1";
  const auto none = Campaign("artifacts " + eval + " --db r.db");
  EXPECT_EQ(none.exit_code, 0) << none.err;
  EXPECT_EQ(none.err, "no artifacts for " + eval + "\n");
  ExpectOneLineError(Campaign("artifacts " + eval + " --db r.db --out out3"), 1,
                     eval + ": no artifacts to export to out3");
  EXPECT_FALSE(fs::exists(dir_ + "/out3"));
}

TEST_F(RlposCampaignCli, UsageErrors) {
  EXPECT_EQ(Campaign("").exit_code, 2);
  EXPECT_EQ(Campaign("run").exit_code, 2);
  EXPECT_EQ(Campaign("results abc --format xml").exit_code, 2);
  EXPECT_EQ(Campaign("run x.json --workers 0").exit_code, 2);
}

}  // namespace
}  // namespace rlpos::testing
