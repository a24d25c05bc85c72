#include "common/store/job_result.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace rlpos {
namespace {

using nlohmann::json;

const json& Field(const json& result, const char* key) {
  if (!result.is_object())
    throw std::invalid_argument("result is not a JSON object");
  if (!result.contains(key)) {
    throw std::invalid_argument(std::string("result has no \"") + key + "\"");
  }
  return result[key];
}

double Finite(const json& v, const char* key) {
  if (!v.is_number() || !std::isfinite(v.get<double>())) {
    throw std::invalid_argument(std::string("result \"") + key + "\" is not a finite number");
  }
  return v.get<double>();
}

std::optional<double> NullableNumber(const json& result, const char* key) {
  const json& v = Field(result, key);
  if (v.is_null())
    return std::nullopt;
  return Finite(v, key);
}

int Count(const json& result, const char* key) {
  const json& v = Field(result, key);
  if (!v.is_number_integer() || v.get<long long>() < 0 || v.get<long long>() > 1000000) {
    throw std::invalid_argument(std::string("result \"") + key + "\" is not a count");
  }
  return v.get<int>();
}

Vec3 Triple(const json& p, const std::string& what) {
  if (!p.is_array() || p.size() != 3)
    throw std::invalid_argument("result \"" + what + "\" is not [x, y, z]");
  return {Finite(p[0], what.c_str()), Finite(p[1], what.c_str()), Finite(p[2], what.c_str())};
}

// A list of 1..kMaxUavs entries under `key`.
const json& UavList(const json& result, const char* key) {
  const json& list = Field(result, key);
  if (!list.is_array() || list.empty() || list.size() > kMaxUavs) {
    throw std::invalid_argument(std::string("result \"") + key + "\" is not a list of 1.." +
                                std::to_string(kMaxUavs) + " UAVs");
  }
  return list;
}

using StoredMetric = MetricDef<std::optional<double>>;
// A result's structure before any metric was added to it: a run's is schema 1, a UAV's 10.
constexpr int kRunKeysSince = 1, kUavKeysSince = 10;

std::optional<double> ReadReal(const json& object, const char* key, bool nullable) {
  if (nullable)
    return NullableNumber(object, key);
  return Finite(Field(object, key), key);
}

// A metric newer than the result's structure may be absent (results of older builds).
template <typename Fields, typename Object>
void ReadMetric(const json& object, const char* key, std::optional<double> Fields::*real,
                int Fields::*count, const StoredMetric& m, int keys_since, Object& out) {
  if (m.since_schema > keys_since && !object.contains(key))
    return;
  if (count) {
    out.*count = Count(object, key);
  } else {
    out.*real = ReadReal(object, key, m.nullable);
  }
}

bool Plausible(const StoredMetric& m, double v) {
  switch (m.range) {
    case MetricRange::kUpTo:
      return v >= 0 && v <= m.max;
    case MetricRange::kRatio:
      return v >= 0 && v <= 1;
    case MetricRange::kPositive:
      return v > 0 && v <= 1;
    case MetricRange::kAny:
      break;
  }
  return true;
}

const char* RangeError(MetricRange range) {
  switch (range) {
    case MetricRange::kRatio:
      return "is not in [0, 1]";
    case MetricRange::kPositive:
      return "is not in (0, 1]";
    default:
      return "is out of range";
  }
}

UavEvalResult ParseUav(const json& entry, std::size_t index) {
  const std::string where = "uavs/" + std::to_string(index);
  if (!entry.is_object())
    throw std::invalid_argument("result \"" + where + "\" is not an object");
  UavEvalResult u;
  const json& name = Field(entry, "name");
  if (!name.is_string() || name.get<std::string>().empty() || name.get<std::string>().size() > 64) {
    throw std::invalid_argument("result \"" + where + "/name\" is not a UAV name");
  }
  u.name = name.get<std::string>();
  u.position = Triple(Field(entry, "position"), where + "/position");
  bool plausible = true;
  for (const auto& m : kStoredMetrics) {
    if (!m.HasUav())
      continue;
    ReadMetric(entry, m.uav_key, m.uav_real, m.uav_count, m, kUavKeysSince, u);
    if (m.uav_real && u.*m.uav_real && !Plausible(m, *(u.*m.uav_real)))
      plausible = false;
  }
  if (!plausible || u.n_los > u.ues_served)
    throw std::invalid_argument("result \"" + where + "\" holds an implausible metric");
  return u;
}

// A single-UAV result's one UAV: its totals.
UavEvalResult OnlyUav(const EvalResult& r) {
  UavEvalResult u;
  u.name = "uav";
  u.position = r.placement.front();
  for (const auto& m : kStoredMetrics) {
    if (m.uav_real)
      u.*m.uav_real = r.*m.run_real;
    if (m.uav_count)
      u.*m.uav_count = r.*m.run_count;
  }
  return u;
}

// Reads the run's metrics, then checks that they are plausible, not only well-formed: a result
// from the network must not poison the statistics.
void ReadRunMetrics(const json& result, EvalResult& r) {
  for (const auto& m : kStoredMetrics)
    ReadMetric(result, m.key, m.run_real, m.run_count, m, kRunKeysSince, r);
  for (const auto& m : kStoredMetrics) {
    if (m.run_real && r.*m.run_real && !Plausible(m, *(r.*m.run_real)))
      throw std::invalid_argument(std::string("result \"") + m.key + "\" " + RangeError(m.range));
  }
  if (r.worst_ue_throughput_mbps && *r.worst_ue_throughput_mbps > *r.aggregate_throughput_mbps)
    throw std::invalid_argument("result \"worst_ue_throughput_mbps\" is out of range");
  if (r.n_los > r.n_ues || r.demands_met > r.n_ues) {
    throw std::invalid_argument("result counts more UEs in LoS or served than \"n_ues\"");
  }
}

// The per-UAV entries must add up to the totals they split.
void CheckUavsAddUp(const EvalResult& r) {
  int ues = 0, n_los = 0;
  double throughput = 0;
  for (const auto& u : r.uavs) {
    ues += u.ues_served;
    n_los += u.n_los;
    throughput += *u.throughput_mbps;
  }
  const double total = *r.aggregate_throughput_mbps;
  if (ues != r.n_ues || n_los != r.n_los ||
      std::fabs(throughput - total) > 1e-6 * std::max(1.0, total)) {
    throw std::invalid_argument("result \"uavs\" do not add up to the run's totals");
  }
}

}  // namespace

bool SamePosition(const Vec3& a, const Vec3& b) {
  const auto off = [](double u, double v) {
    return std::fabs(u - v) > 1e-6 * std::max(1.0, std::fabs(u));
  };
  return !(off(a.x, b.x) || off(a.y, b.y) || off(a.z, b.z));
}

Placement ProducedPlacement(const json& result) {
  const Vec3 first = Triple(Field(result, "position"), "position");
  if (!result.contains("positions"))
    return {first};
  const json& list = UavList(result, "positions");
  Placement placement;
  for (std::size_t i = 0; i < list.size(); ++i)
    placement.push_back(Triple(list[i], "positions/" + std::to_string(i)));
  if (!SamePosition(placement.front(), first))
    throw std::invalid_argument("result \"positions/0\" is not its \"position\"");
  return placement;
}

EvalResult ParseEvalResult(const json& result) {
  EvalResult r;
  const Vec3 first = Triple(Field(result, "position"), "position");
  ReadRunMetrics(result, r);
  if (result.contains("run")) {
    const json& run = result["run"];
    if (!run.is_number_integer() || run.get<long long>() < 0) {
      throw std::invalid_argument("result \"run\" is not an RngRun");
    }
    r.run = run.get<std::uint64_t>();
  }
  if (result.contains("uavs")) {
    const json& list = UavList(result, "uavs");
    for (std::size_t i = 0; i < list.size(); ++i) {
      r.uavs.push_back(ParseUav(list[i], i));
      r.placement.push_back(r.uavs.back().position);
    }
    if (!SamePosition(r.placement.front(), first))
      throw std::invalid_argument("result \"uavs/0/position\" is not its \"position\"");
    CheckUavsAddUp(r);
  } else {
    r.placement = {first};
    r.uavs = {OnlyUav(r)};
  }
  return r;
}

}  // namespace rlpos
