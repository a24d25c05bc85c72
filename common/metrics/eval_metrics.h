#pragma once
// The eval metrics, declared once. Each entry of EvalMetricTable() names a metric's fields in a
// run's result (RunMetricFields) and in a UAV's share (UavMetricFields), its JSON keys, SQL
// columns, unit, plausible range and doc. From it come: the JSON an eval prints
// (run_metrics.cc), the check of a result that comes back (store/job_result.cc), the SQL
// insert and row readers, the schema columns of metrics added after schema 10
// (store/metric_columns.cc), the mean columns of `rlpos-campaign results` and the docs' table
// (`rlpos-sim describe metrics`).
//
// Adding a metric: a field in RunMetricFields (and UavMetricFields when a UAV has its share), an
// entry at the end of the table with .Since(the next schema version), and its computation in
// run_metrics.cc. Its SQL columns are nullable (rows recorded before it have none).
#include <array>
#include <optional>
#include <string>

namespace rlpos {

// The run's metrics over all its UEs. Real is double where the simulator computes them (NaN or
// infinity: undefined), std::optional<double> once read back from JSON or SQL (nullopt: null).
template <typename Real>
struct RunMetricFields {
  Real aggregate_throughput_mbps{};
  Real mean_delay_ms{};
  Real loss_ratio{};
  Real min_snr_db{};
  Real worst_ue_throughput_mbps{};
  Real jain_fairness{};
  int n_los = 0;
  int n_ues = 0;
  int demands_met = 0;
  // Not measured by the packets: the env's reward at the placement by the analytic model, set
  // by whoever evaluates (worker/env/uav_env/analytic_evaluator.h: AnalyticReward).
  Real reward{};
};

// One UAV's share: the same definitions over the UEs it serves.
template <typename Real>
struct UavMetricFields {
  Real throughput_mbps{};
  Real mean_delay_ms{};
  Real loss_ratio{};
  Real worst_ue_throughput_mbps{};
  Real jain_fairness{};
  int n_los = 0;
  int ues_served = 0;
};

// What a result that holds the value outside the range is refused with.
enum class MetricRange {
  kAny,       // any finite number
  kUpTo,      // [0, max]: "is out of range"
  kRatio,     // [0, 1]: "is not in [0, 1]"
  kPositive,  // (0, 1]: "is not in (0, 1]"
};

template <typename Real>
struct MetricDef {
  using RunFields = RunMetricFields<Real>;
  using UavFields = UavMetricFields<Real>;

  // The run's JSON key and metrics column; the value is a real or a count (an integer).
  constexpr MetricDef(const char* key, Real RunFields::*real) : key(key), run_real(real) {}
  constexpr MetricDef(const char* key, int RunFields::*count) : key(key), run_count(count) {}

  // A UAV's JSON key and uav_metrics column, and its field.
  constexpr MetricDef PerUav(const char* k, Real UavFields::*real) const {
    MetricDef d = *this;
    d.uav_key = k;
    d.uav_real = real;
    return d;
  }
  constexpr MetricDef PerUav(const char* k, int UavFields::*count) const {
    MetricDef d = *this;
    d.uav_key = k;
    d.uav_count = count;
    return d;
  }
  constexpr MetricDef Describe(const char* n, const char* u, const char* text) const {
    MetricDef d = *this;
    d.name = n;
    d.unit = u;
    d.doc = text;
    return d;
  }
  // Null in JSON and NULL in SQL where undefined (no packet received, no UE served).
  constexpr MetricDef Nullable() const {
    MetricDef d = *this;
    d.nullable = true;
    return d;
  }
  constexpr MetricDef Range(MetricRange r, double m = 0) const {
    MetricDef d = *this;
    d.range = r;
    d.max = m;
    return d;
  }
  // Its name in the views v_eval_runs and v_eval_uavs, when not its column's.
  constexpr MetricDef View(const char* column) const {
    MetricDef d = *this;
    d.view_column = column;
    return d;
  }
  // The schema version that added its columns; results written before may lack its JSON key.
  constexpr MetricDef Since(int version) const {
    MetricDef d = *this;
    d.since_schema = version;
    return d;
  }
  // Its mean over the runs that have it, in `rlpos-campaign results` and the report: the CSV
  // and JSON column, the table's header, the table's decimals.
  constexpr MetricDef Mean(const char* column, const char* header, int decimals) const {
    MetricDef d = *this;
    d.mean_column = column;
    d.mean_header = header;
    d.mean_decimals = decimals;
    return d;
  }

  bool IsCount() const { return run_count != nullptr; }
  bool HasUav() const { return uav_key != nullptr; }
  const char* RunView() const { return view_column ? view_column : key; }
  const char* UavView() const { return view_column ? view_column : uav_key; }
  const char* SqlType() const { return IsCount() ? "INTEGER" : "REAL"; }

  const char* key;
  Real RunFields::*run_real = nullptr;
  int RunFields::*run_count = nullptr;
  const char* uav_key = nullptr;
  Real UavFields::*uav_real = nullptr;
  int UavFields::*uav_count = nullptr;
  const char* name = "";
  const char* unit = "";
  const char* doc = "";
  bool nullable = false;
  MetricRange range = MetricRange::kAny;
  double max = 0;
  const char* view_column = nullptr;
  int since_schema = 1;
  const char* mean_column = nullptr;
  const char* mean_header = nullptr;
  int mean_decimals = 0;
};

// The table. Its order is the order in which a result's keys are checked and the order of the
// mean columns of the reports (after the ones written by hand).
template <typename Real>
constexpr auto EvalMetricTable() {
  using D = MetricDef<Real>;
  using R = RunMetricFields<Real>;
  using U = UavMetricFields<Real>;
  return std::array{
      D("aggregate_throughput_mbps", &R::aggregate_throughput_mbps)
          .PerUav("throughput_mbps", &U::throughput_mbps)
          .View("throughput_mbps")
          .Range(MetricRange::kUpTo, 1e6)
          .Describe("throughput", "Mbit/s",
                    "Application bytes received at the UAV sink inside the measurement window "
                    "x 8 / window length"),
      D("mean_delay_ms", &R::mean_delay_ms)
          .PerUav("mean_delay_ms", &U::mean_delay_ms)
          .View("delay_ms")
          .Nullable()
          .Range(MetricRange::kUpTo, 1e9)
          .Describe("mean delay", "ms",
                    "Mean one-way delay of the packets received inside the window "
                    "(packet-weighted over the UEs); null when none was received"),
      D("loss_ratio", &R::loss_ratio)
          .PerUav("loss_ratio", &U::loss_ratio)
          .Nullable()
          .Range(MetricRange::kRatio)
          .Describe("loss", "ratio",
                    "Share of the packets sent inside the window that never arrived (late "
                    "arrivals still count as arrived); null when none was sent"),
      D("min_snr_db", &R::min_snr_db)
          .Nullable()
          .Describe("minimum SNR", "dB", "The lowest SNR of a UE's link; null without UEs"),
      D("worst_ue_throughput_mbps", &R::worst_ue_throughput_mbps)
          .PerUav("worst_ue_throughput_mbps", &U::worst_ue_throughput_mbps)
          .View("worst_ue_mbps")
          .Nullable()
          .Range(MetricRange::kUpTo, 1e6)
          .Since(9)
          .Mean("worst_ue_mean_mbps", "worst UE Mbit/s", 2)
          .Describe("worst UE throughput", "Mbit/s",
                    "The lowest per-UE throughput; null when the UAV serves no UE"),
      D("jain_fairness", &R::jain_fairness)
          .PerUav("jain_fairness", &U::jain_fairness)
          .Nullable()
          .Range(MetricRange::kPositive)
          .Since(9)
          .Mean("jain_mean", "Jain", 3)
          .Describe("Jain's fairness", "index",
                    "(sum x_i)^2 / (n sum x_i^2) over the per-UE throughputs x_i, from 1/n (one "
                    "UE gets everything) to 1 (all equal); null when no UE received anything"),
      D("n_los", &R::n_los)
          .PerUav("n_los", &U::n_los)
          .Describe("UEs in LoS", "count",
                    "UEs whose link to their UAV is geometrically clear of every building"),
      D("n_ues", &R::n_ues)
          .PerUav("ues_served", &U::ues_served)
          .Describe("UEs", "count", "UEs of the scenario (of a UAV: the UEs it serves)"),
      D("demands_met", &R::demands_met)
          .Describe("demands met", "count",
                    "UEs whose SNR reaches the minimum SNR of the MCS their demand needs"),
      D("reward", &R::reward)
          .Nullable()
          .Range(MetricRange::kUpTo, 1e6)
          .Since(11)
          .Describe("reward", "env.reward",
                    "The env's reward at the placement (the scenario's env.reward) by the "
                    "analytic model, as the agent and the oracle score it: the same in every "
                    "RngRun. rl's over the oracle's is a campaign's optimality; null when not "
                    "computed"),
  };
}

// The table for the simulator's values (double), where the docs and schema read it.
inline constexpr auto kEvalMetrics = EvalMetricTable<double>();
// The table for the store's values (null: undefined, or recorded before the metric existed).
inline constexpr auto kStoredMetrics = EvalMetricTable<std::optional<double>>();

// The table as a Markdown table (metric, unit, JSON key, SQL column, doc), for the docs.
std::string EvalMetricsMarkdown();

}  // namespace rlpos
