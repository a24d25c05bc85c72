#include "campaign/expanded_campaign_json.h"

#include <stdexcept>

namespace rlpos {
namespace {

using nlohmann::json;

json ToJson(const Job& job) {
  json j = {{"id", job.id},
            {"key", job.key},
            {"kind", ToString(job.kind)},
            {"scenario", job.scenario},
            {"label", job.label},
            {"rng_run", nullptr},
            {"train_seed", nullptr},
            {"depends_on", job.depends_on},
            {"position", ToJson(job.position)},
            {"argv", job.argv}};
  if (job.rng_run)
    j["rng_run"] = *job.rng_run;
  if (job.train_seed)
    j["train_seed"] = *job.train_seed;
  return j;
}

template <typename T>
T Field(const json& j, const char* name, const std::string& where) {
  if (!j.is_object() || !j.contains(name)) {
    throw std::invalid_argument(where + ": missing \"" + name + "\"");
  }
  try {
    return j.at(name).get<T>();
  } catch (const json::exception&) {
    throw std::invalid_argument(where + ": \"" + name + "\" has the wrong type");
  }
}

std::optional<std::uint64_t> OptionalUnsigned(const json& j, const char* name,
                                              const std::string& where) {
  if (!j.contains(name) || j.at(name).is_null())
    return std::nullopt;
  return Field<std::uint64_t>(j, name, where);
}

Job JobFromJson(const json& j, const std::string& where) {
  Job job;
  job.id = Field<std::string>(j, "id", where);
  job.key = Field<std::string>(j, "key", where);
  try {
    job.kind = ParseJobKind(Field<std::string>(j, "kind", where));
  } catch (const std::invalid_argument&) {
    throw std::invalid_argument(where + ": unknown \"kind\"");
  }
  job.scenario = Field<std::string>(j, "scenario", where);
  job.label = Field<std::string>(j, "label", where);
  job.rng_run = OptionalUnsigned(j, "rng_run", where);
  job.train_seed = OptionalUnsigned(j, "train_seed", where);
  job.depends_on = Field<std::string>(j, "depends_on", where);
  try {
    job.position = PositionRuleFromJson(Field<json>(j, "position", where));
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(where + "/position: " + e.what());
  }
  job.argv = Field<std::vector<std::string>>(j, "argv", where);
  return job;
}

}  // namespace

json ToJson(const ExpandedCampaign& campaign) {
  json jobs = json::array();
  for (const auto& job : campaign.jobs)
    jobs.push_back(ToJson(job));
  return {{"id", campaign.id},
          {"name", campaign.name},
          {"spec", campaign.spec},
          {"max_attempts", campaign.max_attempts},
          {"job_timeout_s", campaign.job_timeout_s},
          {"jobs", jobs}};
}

ExpandedCampaign ExpandedCampaignFromJson(const json& j) {
  const std::string where = "campaign";
  ExpandedCampaign c;
  c.id = Field<std::string>(j, "id", where);
  c.name = Field<std::string>(j, "name", where);
  c.spec = Field<json>(j, "spec", where);
  c.max_attempts = Field<int>(j, "max_attempts", where);
  c.job_timeout_s = Field<double>(j, "job_timeout_s", where);
  if (c.max_attempts < 1)
    throw std::invalid_argument(where + ": \"max_attempts\" must be >= 1");
  if (!(c.job_timeout_s > 0)) {
    throw std::invalid_argument(where + ": \"job_timeout_s\" must be > 0");
  }
  const json jobs = Field<json>(j, "jobs", where);
  if (!jobs.is_array())
    throw std::invalid_argument(where + ": \"jobs\" is not an array");
  for (std::size_t i = 0; i < jobs.size(); ++i) {
    c.jobs.push_back(JobFromJson(jobs[i], where + "/jobs/" + std::to_string(i)));
  }
  return c;
}

}  // namespace rlpos
