#include "worker/programs/rl_commands/generalist_checkpoint.h"

#include <fstream>
#include <nlohmann/json.hpp>

#include "common/config/config_error.h"

namespace rlpos::sim {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

constexpr const char* kAgentFile = "agent.state";
constexpr const char* kProgressFile = "progress.json";

json ScoresJson(const std::vector<ValidationScore>& scores) {
  json rows = json::array();
  for (const auto& s : scores) {
    rows.push_back({s.origin, s.final_reward, s.oracle_reward, s.ratio, s.n_los, s.n_ues});
  }
  return rows;
}

std::vector<ValidationScore> ScoresOf(const json& rows) {
  std::vector<ValidationScore> scores;
  for (const auto& r : rows) {
    scores.push_back({r.at(0).get<std::string>(), r.at(1).get<double>(), r.at(2).get<double>(),
                      r.at(3).get<double>(), r.at(4).get<int>(), r.at(5).get<std::size_t>()});
  }
  return scores;
}

}  // namespace

GeneralistCheckpoint::GeneralistCheckpoint(fs::path partial, std::string fingerprint)
    : dir_(std::move(partial) / "checkpoint"), fingerprint_(std::move(fingerprint)) {}

fs::path GeneralistCheckpoint::Current() const {
  std::error_code ec;
  if (fs::exists(dir_ / kProgressFile, ec))
    return dir_;
  const fs::path old = dir_.string() + ".old";  // a kill between the two renames of Save
  if (fs::exists(old / kProgressFile, ec))
    return old;
  return {};
}

bool GeneralistCheckpoint::Exists() const {
  return !Current().empty();
}

std::optional<SavedCheckpoint> GeneralistCheckpoint::Find() const {
  if (!Exists())
    return std::nullopt;
  const std::string where = dir_.parent_path().string();
  try {
    std::ifstream in(Current() / kProgressFile);
    const json p = json::parse(in);
    if (p.at("fingerprint") != fingerprint_) {
      throw ConfigError("--out", where +
                                     " holds the checkpoint of another training (other settings "
                                     "or budget); remove it or give another --out");
    }
    SavedCheckpoint c;
    GeneralistResult& r = c.state.result;
    r.steps = p.at("steps").get<std::int64_t>();
    r.episodes = p.at("episodes").get<std::int64_t>();
    r.kept_at_steps = p.at("kept_at_steps").get<std::int64_t>();
    r.validation = ScoresOf(p.at("validation"));
    if (!p.at("best").is_null())
      c.state.best = p.at("best").get<double>();
    c.state.next_validation = p.at("next_validation").get<std::int64_t>();
    c.curve_bytes = p.at("curve_bytes").get<std::uint64_t>();
    c.seconds = p.at("seconds").get<double>();
    return c;
  } catch (const json::exception& e) {
    throw ConfigError("--out", where + "/checkpoint/progress.json: " + e.what() + "; remove " +
                                   where + " to start again");
  }
}

void GeneralistCheckpoint::LoadAgent(PpoAgent& agent) const {
  try {
    agent.LoadTrainingState((Current() / kAgentFile).string());
  } catch (const std::runtime_error& e) {
    throw ConfigError("--out", std::string(e.what()) + "; remove " + dir_.parent_path().string() +
                                   " to start again");
  }
}

void GeneralistCheckpoint::Save(const GeneralistState& state, const PpoAgent& agent,
                                std::uint64_t curve_bytes, double seconds) const {
  const fs::path next = dir_.string() + ".next";
  fs::remove_all(next);
  fs::create_directories(next);
  agent.SaveTrainingState((next / kAgentFile).string());
  const GeneralistResult& r = state.result;
  const json progress = {{"fingerprint", fingerprint_},
                         {"steps", r.steps},
                         {"episodes", r.episodes},
                         {"kept_at_steps", r.kept_at_steps},
                         {"validation", ScoresJson(r.validation)},
                         {"best", state.best ? json(*state.best) : json(nullptr)},
                         {"next_validation", state.next_validation},
                         {"curve_bytes", curve_bytes},
                         {"seconds", seconds}};
  {
    std::ofstream out(next / kProgressFile);
    out << progress.dump() << '\n';
    if (!out.flush())
      throw std::runtime_error((next / kProgressFile).string() + ": cannot write");
  }
  // The old one is set aside, the new one put in its place, then the old one removed: a kill at
  // any point leaves a whole checkpoint under one of the two names (Find looks at both).
  const fs::path old = dir_.string() + ".old";
  fs::remove_all(old);
  if (fs::exists(dir_))
    fs::rename(dir_, old);
  fs::rename(next, dir_);
  fs::remove_all(old);
}

void GeneralistCheckpoint::Remove() const {
  std::error_code ec;
  fs::remove_all(dir_, ec);
  fs::remove_all(dir_.string() + ".next", ec);
  fs::remove_all(dir_.string() + ".old", ec);
}

}  // namespace rlpos::sim
