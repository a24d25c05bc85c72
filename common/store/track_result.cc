#include "common/store/track_result.h"

#include <cmath>
#include <limits>
#include <stdexcept>

#include "common/campaign/campaign_spec.h"
#include "common/scenario/names.h"
#include "common/scenario/number_text.h"
#include "common/stats/descriptive.h"

namespace rlpos {
namespace {

using nlohmann::json;

std::string JoinKey(const std::string& where, const std::string& key) {
  return where.empty() ? key : where + "/" + key;
}

[[noreturn]] void Bad(const std::string& key, const std::string& problem) {
  throw std::invalid_argument("result \"" + key + "\" " + problem);
}

const json& Field(const json& object, const std::string& key, const std::string& where) {
  if (!object.is_object())
    throw std::invalid_argument("result " + (where.empty() ? "" : "\"" + where + "\" ") +
                                "is not a JSON object");
  if (!object.contains(key))
    throw std::invalid_argument("result has no \"" + JoinKey(where, key) + "\"");
  return object[key];
}

double Number(const json& object, const std::string& key, const std::string& where, double low,
              double high) {
  const json& v = Field(object, key, where);
  if (!v.is_number() || !std::isfinite(v.get<double>()) || v.get<double>() < low ||
      v.get<double>() > high) {
    Bad(JoinKey(where, key),
        "is not a number in [" + FormatNumber(low) + ", " + FormatNumber(high) + "]");
  }
  return v.get<double>();
}

long long Integer(const json& object, const std::string& key, long long low, long long high) {
  const json& v = Field(object, key, "");
  if (!v.is_number_integer() || v.get<long long>() < low || v.get<long long>() > high)
    Bad(key, "is not an integer in " + std::to_string(low) + ".." + std::to_string(high));
  return v.get<long long>();
}

std::string Name(const json& object, const std::string& key,
                 const std::vector<std::string>& known) {
  const json& v = Field(object, key, "");
  if (v.is_string()) {
    for (const std::string& name : known) {
      if (v.get<std::string>() == name)
        return name;
    }
  }
  Bad(key, "is not a known name");
}

double High(const TrackMetricDef& m) {
  return m.range == MetricRange::kRatio ? 1.0 : m.max;
}

Placement Positions(const json& v, const std::string& where) {
  if (!v.is_array() || v.empty() || v.size() > kMaxUavs)
    Bad(where, "is not a list of 1.." + std::to_string(kMaxUavs) + " positions");
  Placement out;
  for (const json& p : v) {
    if (!p.is_array() || p.size() != 3)
      Bad(where, "holds a position that is not [x, y, z]");
    Vec3 q;
    double* c[] = {&q.x, &q.y, &q.z};
    for (std::size_t i = 0; i < 3; ++i) {
      if (!p[i].is_number() || !std::isfinite(p[i].get<double>()))
        Bad(where, "holds a coordinate that is not a finite number");
      *c[i] = p[i].get<double>();
    }
    out.push_back(q);
  }
  return out;
}

TrackIntervalRow Interval(const json& v, std::size_t index, int n_ues, bool packet) {
  const std::string where = "series/" + std::to_string(index);
  TrackIntervalRow row;
  row.time_s = Number(v, "time", where, 0, 86400);
  const json& scored = Field(v, "scored", where);
  if (!scored.is_boolean())
    Bad(where + "/scored", "is not true or false");
  row.scored = scored.get<bool>();
  row.reward = Number(v, "reward", where, 0, 1e6);
  row.throughput_mbps = Number(v, "throughput_mbps", where, 0, 1e6);
  row.los_share = Number(v, "n_los", where, 0, n_ues) / n_ues;
  row.demands_met_share = Number(v, "demands_met", where, 0, n_ues) / n_ues;
  if (packet && !Field(v, "mean_delay_ms", where).is_null())
    row.delay_ms = Number(v, "mean_delay_ms", where, 0, 1e9);
  row.positions = Positions(Field(v, "positions", where), where + "/positions");
  return row;
}

// The same number computed twice, in other orders: equal to a few ulps of the larger.
bool Agrees(double reported, double recomputed) {
  return std::abs(reported - recomputed) <=
         1e-9 * std::max({1.0, std::abs(reported), std::abs(recomputed)});
}

}  // namespace

TrackRunResult ParseTrackResult(const json& result) {
  if (!result.is_object())
    throw std::invalid_argument("result is not a JSON object");
  TrackRunResult out;
  out.positioner = Name(result, "positioner", NameList(kTrackPositioners));
  out.fidelity = Name(result, "fidelity", NameList(kFidelities));
  out.run = static_cast<std::uint64_t>(Integer(result, "run", 1, 4294967295LL));
  out.duration_s = Number(result, "duration", "", 1e-9, 86400);
  out.decision_interval_s = Number(result, "decision_interval", "", 1e-9, 86400);
  const auto n_ues = static_cast<int>(Integer(result, "n_ues", 1, 1000000));
  const long long count = Integer(result, "intervals", 1, kMaxTrackIntervals);
  out.scored_intervals = static_cast<int>(Integer(result, "scored_intervals", 1, count));
  for (const TrackMetricDef& m : kTrackMetrics) {
    if (m.nullable && Field(result, m.key, "").is_null()) {
      out.metrics.*(m.field) = std::numeric_limits<double>::quiet_NaN();
      continue;
    }
    out.metrics.*(m.field) = Number(result, m.key, "", 0, High(m));
  }
  const json& series = Field(result, "series", "");
  if (!series.is_array() || static_cast<long long>(series.size()) != count)
    Bad("series", "does not list the run's " + std::to_string(count) + " intervals");
  const bool packet = out.fidelity == "packet";
  std::vector<double> rewards;
  for (std::size_t i = 0; i < series.size(); ++i) {
    TrackIntervalRow row = Interval(series[i], i, n_ues, packet);
    if (!out.intervals.empty() && !(row.time_s > out.intervals.back().time_s))
      Bad("series/" + std::to_string(i) + "/time", "does not come after the interval before");
    if (!out.intervals.empty() && row.positions.size() != out.intervals.front().positions.size())
      Bad("series/" + std::to_string(i) + "/positions", "has another number of UAVs");
    if (row.scored)
      rewards.push_back(row.reward);
    out.intervals.push_back(std::move(row));
  }
  if (static_cast<int>(rewards.size()) != out.scored_intervals)
    Bad("scored_intervals", "is not the number of scored intervals in the series");
  if (!Agrees(out.metrics.mean_reward, Mean(rewards)) ||
      !Agrees(out.metrics.reward_p5, Quantile(rewards, 0.05))) {
    Bad("mean_reward", "or \"reward_p5\" does not add up from the series");
  }
  return out;
}

}  // namespace rlpos
