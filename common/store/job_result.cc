#include "common/store/job_result.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace rlpos {
namespace {

using nlohmann::json;

const json& Field(const json& result, const char* key) {
  if (!result.is_object()) throw std::invalid_argument("result is not a JSON object");
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
  if (v.is_null()) return std::nullopt;
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

UavEvalResult ParseUav(const json& entry, std::size_t index) {
  const std::string where = "uavs/" + std::to_string(index);
  if (!entry.is_object())
    throw std::invalid_argument("result \"" + where + "\" is not an object");
  UavEvalResult u;
  const json& name = Field(entry, "name");
  if (!name.is_string() || name.get<std::string>().empty() ||
      name.get<std::string>().size() > 64) {
    throw std::invalid_argument("result \"" + where + "/name\" is not a UAV name");
  }
  u.name = name.get<std::string>();
  u.position = Triple(Field(entry, "position"), where + "/position");
  u.ues_served = Count(entry, "ues_served");
  u.throughput_mbps = Finite(Field(entry, "throughput_mbps"), "throughput_mbps");
  u.mean_delay_ms = NullableNumber(entry, "mean_delay_ms");
  u.loss_ratio = NullableNumber(entry, "loss_ratio");
  u.n_los = Count(entry, "n_los");
  u.worst_ue_throughput_mbps = NullableNumber(entry, "worst_ue_throughput_mbps");
  u.jain_fairness = NullableNumber(entry, "jain_fairness");
  if (u.throughput_mbps < 0 || (u.mean_delay_ms && *u.mean_delay_ms < 0) ||
      (u.loss_ratio && (*u.loss_ratio < 0 || *u.loss_ratio > 1)) ||
      (u.worst_ue_throughput_mbps && *u.worst_ue_throughput_mbps < 0) ||
      (u.jain_fairness && (*u.jain_fairness <= 0 || *u.jain_fairness > 1)) ||
      u.n_los > u.ues_served) {
    throw std::invalid_argument("result \"" + where + "\" holds an implausible metric");
  }
  return u;
}

// A single-UAV result's one UAV: its totals.
UavEvalResult OnlyUav(const EvalResult& r) {
  return {"uav",
          r.placement.front(),
          r.n_ues,
          r.aggregate_throughput_mbps,
          r.mean_delay_ms,
          r.loss_ratio,
          r.worst_ue_throughput_mbps,
          r.jain_fairness,
          r.n_los};
}

// The per-UAV entries must add up to the totals they split.
void CheckUavsAddUp(const EvalResult& r) {
  int ues = 0, n_los = 0;
  double throughput = 0;
  for (const auto& u : r.uavs) {
    ues += u.ues_served;
    n_los += u.n_los;
    throughput += u.throughput_mbps;
  }
  if (ues != r.n_ues || n_los != r.n_los ||
      std::fabs(throughput - r.aggregate_throughput_mbps) >
          1e-6 * std::max(1.0, r.aggregate_throughput_mbps)) {
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
  r.aggregate_throughput_mbps =
      Finite(Field(result, "aggregate_throughput_mbps"), "aggregate_throughput_mbps");
  r.mean_delay_ms = NullableNumber(result, "mean_delay_ms");
  r.loss_ratio = NullableNumber(result, "loss_ratio");
  r.min_snr_db = NullableNumber(result, "min_snr_db");
  if (result.contains("worst_ue_throughput_mbps"))
    r.worst_ue_throughput_mbps = NullableNumber(result, "worst_ue_throughput_mbps");
  if (result.contains("jain_fairness"))
    r.jain_fairness = NullableNumber(result, "jain_fairness");
  r.n_los = Count(result, "n_los");
  r.n_ues = Count(result, "n_ues");
  r.demands_met = Count(result, "demands_met");
  // Plausible, not only well-formed: a result from the network must not poison the statistics.
  if (r.aggregate_throughput_mbps < 0 || r.aggregate_throughput_mbps > 1e6) {
    throw std::invalid_argument("result \"aggregate_throughput_mbps\" is out of range");
  }
  if (r.mean_delay_ms && (*r.mean_delay_ms < 0 || *r.mean_delay_ms > 1e9)) {
    throw std::invalid_argument("result \"mean_delay_ms\" is out of range");
  }
  if (r.loss_ratio && (*r.loss_ratio < 0 || *r.loss_ratio > 1)) {
    throw std::invalid_argument("result \"loss_ratio\" is not in [0, 1]");
  }
  if (r.worst_ue_throughput_mbps &&
      (*r.worst_ue_throughput_mbps < 0 || *r.worst_ue_throughput_mbps > r.aggregate_throughput_mbps)) {
    throw std::invalid_argument("result \"worst_ue_throughput_mbps\" is out of range");
  }
  if (r.jain_fairness && (*r.jain_fairness <= 0 || *r.jain_fairness > 1)) {
    throw std::invalid_argument("result \"jain_fairness\" is not in (0, 1]");
  }
  if (r.n_los > r.n_ues || r.demands_met > r.n_ues) {
    throw std::invalid_argument("result counts more UEs in LoS or served than \"n_ues\"");
  }
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
