#include "campaign/expanded_campaign_json.h"

#include <gtest/gtest.h>

#include <initializer_list>
#include <stdexcept>
#include <string>

#include "test_support.h"

namespace rlpos {
namespace {

using nlohmann::json;

void ExpectSameBox(const Box& a, const Box& b, const std::string& where) {
  EXPECT_DOUBLE_EQ(a.xmin, b.xmin) << where;
  EXPECT_DOUBLE_EQ(a.xmax, b.xmax) << where;
  EXPECT_DOUBLE_EQ(a.ymin, b.ymin) << where;
  EXPECT_DOUBLE_EQ(a.ymax, b.ymax) << where;
  EXPECT_DOUBLE_EQ(a.zmin, b.zmin) << where;
  EXPECT_DOUBLE_EQ(a.zmax, b.zmax) << where;
}

// The error of ExpandedCampaignFromJson(j); fails the test if it does not throw.
std::string ErrorOf(const json& j) {
  try {
    ExpandedCampaignFromJson(j);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  ADD_FAILURE() << "no std::invalid_argument for " << j.dump().substr(0, 200);
  return "";
}

void ExpectErrorNames(const json& j, std::initializer_list<const char*> parts) {
  const std::string error = ErrorOf(j);
  for (const char* part : parts)
    EXPECT_NE(error.find(part), std::string::npos) << error;
}

TEST(ExpandedCampaignJson, RoundTripKeepsEveryField) {
  const ExpandedCampaign original = testing::MiniCampaign();
  ASSERT_EQ(original.jobs.size(), 44u);
  // Through text, as it travels in a CampaignRequest.
  const ExpandedCampaign back = ExpandedCampaignFromJson(json::parse(ToJson(original).dump()));

  EXPECT_EQ(back.id, original.id);
  EXPECT_EQ(back.name, "mini");
  EXPECT_EQ(back.spec, original.spec);
  EXPECT_EQ(back.max_attempts, 2);  // 1 + "retries": 1
  EXPECT_DOUBLE_EQ(back.job_timeout_s, 300.0);
  ASSERT_EQ(back.jobs.size(), original.jobs.size());
  int with_dependency = 0, with_offset = 0, with_obstacles = 0;
  for (std::size_t i = 0; i < original.jobs.size(); ++i) {
    const Job& a = original.jobs[i];
    const Job& b = back.jobs[i];
    SCOPED_TRACE(a.key);
    EXPECT_EQ(b.id, a.id);
    EXPECT_EQ(b.key, a.key);
    EXPECT_EQ(b.kind, a.kind);
    EXPECT_EQ(b.scenario, a.scenario);
    EXPECT_EQ(b.label, a.label);
    EXPECT_EQ(b.rng_run, a.rng_run);
    EXPECT_EQ(b.train_seed, a.train_seed);
    EXPECT_EQ(b.depends_on, a.depends_on);
    EXPECT_EQ(b.argv, a.argv);
    EXPECT_EQ(b.position.offset, a.position.offset);
    EXPECT_DOUBLE_EQ(b.position.distance, a.position.distance);
    if (a.position.offset > 0) {
      ExpectSameBox(b.position.geometry.bounds, a.position.geometry.bounds, "bounds");
      ASSERT_EQ(b.position.geometry.obstacles.size(), a.position.geometry.obstacles.size());
      for (std::size_t k = 0; k < a.position.geometry.obstacles.size(); ++k) {
        ExpectSameBox(b.position.geometry.obstacles[k], a.position.geometry.obstacles[k],
                      "obstacle " + std::to_string(k));
      }
      ++with_offset;
      if (!a.position.geometry.obstacles.empty())
        ++with_obstacles;
    }
    if (!a.depends_on.empty())
      ++with_dependency;
  }
  // The campaign exercises every part of the format.
  EXPECT_GT(with_dependency, 0);
  EXPECT_GT(with_offset, 0);
  EXPECT_GT(with_obstacles, 0);

  const Job& eval = testing::FindJob(back, "eval/B/offset3/run2");
  EXPECT_EQ(eval.kind, JobKind::kEval);
  EXPECT_EQ(eval.rng_run, 2u);
  EXPECT_EQ(eval.train_seed, 1u);
  EXPECT_EQ(eval.depends_on, back.id + "/train/B/seed1");
  EXPECT_EQ(eval.position.offset, 3);
  const Job& train = testing::FindJob(back, "train/B/seed1");
  EXPECT_EQ(train.kind, JobKind::kTrain);
  EXPECT_FALSE(train.rng_run.has_value());
  EXPECT_TRUE(train.depends_on.empty());
  ASSERT_FALSE(train.argv.empty());
  EXPECT_EQ(train.argv[0], "rlpos-sim");
}

TEST(ExpandedCampaignJson, NullAndMissingOptionalNumbersReadAsNone) {
  json j = ToJson(testing::MiniCampaign());
  j["jobs"][0]["rng_run"] = nullptr;
  j["jobs"][0].erase("train_seed");
  const ExpandedCampaign c = ExpandedCampaignFromJson(j);
  EXPECT_FALSE(c.jobs[0].rng_run.has_value());
  EXPECT_FALSE(c.jobs[0].train_seed.has_value());
}

TEST(ExpandedCampaignJson, MalformedCampaignNamesTheField) {
  const json good = ToJson(testing::MiniCampaign());
  ExpectErrorNames(json::array(), {"campaign", "missing \"id\""});
  {
    json j = good;
    j.erase("id");
    ExpectErrorNames(j, {"campaign: missing \"id\""});
  }
  {
    json j = good;
    j["name"] = 7;
    ExpectErrorNames(j, {"campaign", "\"name\"", "wrong type"});
  }
  {
    json j = good;
    j["max_attempts"] = "three";
    ExpectErrorNames(j, {"\"max_attempts\"", "wrong type"});
  }
  {
    json j = good;
    j["max_attempts"] = 0;
    ExpectErrorNames(j, {"\"max_attempts\" must be >= 1"});
  }
  {
    json j = good;
    j["job_timeout_s"] = 0;
    ExpectErrorNames(j, {"\"job_timeout_s\" must be > 0"});
  }
  {
    json j = good;
    j["jobs"] = json::object();
    ExpectErrorNames(j, {"\"jobs\" is not an array"});
  }
}

TEST(ExpandedCampaignJson, MalformedJobNamesItsIndexAndField) {
  const json good = ToJson(testing::MiniCampaign());
  {
    json j = good;
    j["jobs"][3].erase("argv");
    ExpectErrorNames(j, {"campaign/jobs/3", "missing \"argv\""});
  }
  {
    json j = good;
    j["jobs"][5]["argv"] = {"rlpos-sim", 3};
    ExpectErrorNames(j, {"campaign/jobs/5", "\"argv\"", "wrong type"});
  }
  {
    json j = good;
    j["jobs"][0]["kind"] = "bake";
    ExpectErrorNames(j, {"campaign/jobs/0", "unknown \"kind\""});
  }
  {
    json j = good;
    j["jobs"][1]["rng_run"] = "one";
    ExpectErrorNames(j, {"campaign/jobs/1", "\"rng_run\"", "wrong type"});
  }
  {
    json j = good;
    j["jobs"][2]["depends_on"] = nullptr;
    ExpectErrorNames(j, {"campaign/jobs/2", "\"depends_on\""});
  }
  {
    json j = good;
    j["jobs"][4]["position"] = {{"offset", 9}};
    ExpectErrorNames(j, {"campaign/jobs/4/position", "offset 9"});
  }
  {
    json j = good;
    j["jobs"][4]["position"] = {{"offset", 2}, {"distance", 10}};
    ExpectErrorNames(j, {"campaign/jobs/4/position", "distance, bounds and obstacles"});
  }
  {
    json j = good;
    j["jobs"][6] = "not a job";
    ExpectErrorNames(j, {"campaign/jobs/6", "missing \"id\""});
  }
}

}  // namespace
}  // namespace rlpos
