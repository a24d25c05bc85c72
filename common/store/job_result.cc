#include "store/job_result.h"

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

}  // namespace

Vec3 ProducedPosition(const json& result) {
  const json& p = Field(result, "position");
  if (!p.is_array() || p.size() != 3) {
    throw std::invalid_argument("result \"position\" is not [x, y, z]");
  }
  return {Finite(p[0], "position"), Finite(p[1], "position"), Finite(p[2], "position")};
}

EvalResult ParseEvalResult(const json& result) {
  EvalResult r;
  r.position = ProducedPosition(result);
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
  return r;
}

}  // namespace rlpos
