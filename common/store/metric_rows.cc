#include "common/store/metric_rows.h"

#include "common/store/run_key_columns.h"
#include "common/store/sqlite_db.h"

namespace rlpos {
namespace {

// "a, b, c" from the metrics' `column` (the run's or a UAV's).
template <typename Column>
std::string ColumnList(Column column) {
  std::string out;
  for (const auto& m : kStoredMetrics) {
    if (const char* name = column(m))
      out += std::string(", ") + name;
  }
  return out;
}

std::string Placeholders(int count) {
  std::string out = "?";
  for (int i = 1; i < count; ++i)
    out += ", ?";
  return out;
}

// Binds the metrics held in `fields` (real_of, count_of: the metric's member of that side).
template <typename Fields, typename Real, typename Count>
void BindMetrics(Statement& insert, const Fields& fields, Real real_of, Count count_of) {
  for (const auto& m : kStoredMetrics) {
    if (const auto real = real_of(m)) {
      insert.Bind(fields.*real);
    } else if (const auto count = count_of(m)) {
      insert.Bind(fields.*count);
    }
  }
}

// The metrics' result columns of `select`, named by `column` (the run's or a UAV's view names),
// in the order of kStoredMetrics; none for a metric that side lacks.
template <typename Column>
std::vector<std::optional<ResultColumn>> MetricColumns(const Statement& select, Column column) {
  std::vector<std::optional<ResultColumn>> out;
  for (const auto& m : kStoredMetrics) {
    const char* name = column(m);
    out.push_back(name ? std::optional<ResultColumn>(select.Column(name)) : std::nullopt);
  }
  return out;
}

// Reads the metrics from their `columns` (MetricColumns).
template <typename Fields, typename Real, typename Count>
void ReadMetrics(const Statement& select, const std::vector<std::optional<ResultColumn>>& columns,
                 Fields& fields, Real real_of, Count count_of) {
  for (std::size_t i = 0; i < kStoredMetrics.size(); ++i) {
    const auto& m = kStoredMetrics[i];
    if (!columns[i])
      continue;
    if (const auto real = real_of(m)) {
      fields.*real = select.OptionalDouble(*columns[i]);
    } else if (const auto count = count_of(m)) {
      fields.*count = static_cast<int>(select.Int(*columns[i]));
    }
  }
}

using Def = MetricDef<std::optional<double>>;
const auto kRunColumn = [](const Def& m) { return m.key; };
const auto kRunView = [](const Def& m) { return m.RunView(); };
const auto kRunReal = [](const Def& m) { return m.run_real; };
const auto kRunCount = [](const Def& m) { return m.run_count; };
const auto kUavColumn = [](const Def& m) { return m.uav_key; };
const auto kUavView = [](const Def& m) { return m.HasUav() ? m.UavView() : nullptr; };
const auto kUavReal = [](const Def& m) { return m.uav_real; };
const auto kUavCount = [](const Def& m) { return m.uav_count; };

// What the rows of v_eval_runs and v_eval_uavs share: the run, a position and the metrics of
// that side (view: kRunView or kUavView).
struct EvalRowColumns {
  template <typename View>
  EvalRowColumns(const Statement& select, View view)
      : run_key(select),
        x(select.Column("x")),
        y(select.Column("y")),
        z(select.Column("z")),
        metrics(MetricColumns(select, view)) {}

  // Row: MetricRow or UavMetricRow, with the real_of and count_of of its side.
  template <typename Row, typename Real, typename Count>
  void Read(const Statement& select, Row& row, Real real_of, Count count_of) const {
    run_key.Read(select, row);
    row.x = select.Double(x);
    row.y = select.Double(y);
    row.z = select.Double(z);
    ReadMetrics(select, metrics, row, real_of, count_of);
  }

  RunKeyColumns run_key;
  ResultColumn x, y, z;
  std::vector<std::optional<ResultColumn>> metrics;
};

int CountOf(const std::string& columns) {
  int commas = 0;
  for (const char c : columns)
    commas += c == ',' ? 1 : 0;
  return commas;
}

}  // namespace

void InsertEvalMetrics(Database& db, const EvalRowKey& key, const EvalResult& eval) {
  // job_id is the primary key: a second row for the same job cannot exist.
  const std::string run_columns = ColumnList(kRunColumn);
  Statement run =
      db.Prepare("INSERT INTO metrics (job_id, campaign_id, scenario, label, rng_run, x, y, z" +
                 run_columns + ") VALUES (" + Placeholders(8 + CountOf(run_columns)) + ")");
  const Vec3& first = eval.placement.front();
  run.Bind(key.job_id).Bind(key.campaign_id).Bind(key.scenario).Bind(key.label);
  run.Bind(key.rng_run).Bind(first.x).Bind(first.y).Bind(first.z);
  BindMetrics(run, eval, kRunReal, kRunCount);
  run.Run();
  const std::string uav_columns = ColumnList(kUavColumn);
  Statement uav = db.Prepare(
      "INSERT INTO uav_metrics (job_id, uav, name, campaign_id, scenario, label, rng_run, x, y, "
      "z" +
      uav_columns + ") VALUES (" + Placeholders(10 + CountOf(uav_columns)) + ")");
  for (std::size_t i = 0; i < eval.uavs.size(); ++i) {
    const UavEvalResult& u = eval.uavs[i];
    uav.Reset();
    uav.Bind(key.job_id).Bind(static_cast<std::int64_t>(i)).Bind(u.name).Bind(key.campaign_id);
    uav.Bind(key.scenario).Bind(key.label).Bind(key.rng_run);
    uav.Bind(u.position.x).Bind(u.position.y).Bind(u.position.z);
    BindMetrics(uav, u, kUavReal, kUavCount);
    uav.Run();
  }
}

const std::string kOfCampaignInOrder = OfCampaignInOrder();

std::vector<MetricRow> ReadMetricRows(Database& db, const std::string& campaign_id) {
  Statement select = db.Prepare("SELECT job_id, scenario, positioner, rng_run, x, y, z" +
                                ColumnList(kRunView) + " FROM v_eval_runs" + kOfCampaignInOrder);
  select.Bind(campaign_id);
  const EvalRowColumns columns(select, kRunView);
  std::vector<MetricRow> out;
  while (select.Step()) {
    MetricRow m;
    columns.Read(select, m, kRunReal, kRunCount);
    out.push_back(std::move(m));
  }
  return out;
}

std::vector<UavMetricRow> ReadUavMetricRows(Database& db, const std::string& campaign_id) {
  Statement select =
      db.Prepare("SELECT job_id, scenario, positioner, rng_run, uav, uav_name, x, y, z" +
                 ColumnList(kUavView) + " FROM v_eval_uavs" + kOfCampaignInOrder + ", uav");
  select.Bind(campaign_id);
  const EvalRowColumns columns(select, kUavView);
  const ResultColumn uav = select.Column("uav"), name = select.Column("uav_name");
  std::vector<UavMetricRow> out;
  while (select.Step()) {
    UavMetricRow m;
    columns.Read(select, m, kUavReal, kUavCount);
    m.uav = static_cast<int>(select.Int(uav));
    m.name = select.Text(name);
    out.push_back(std::move(m));
  }
  return out;
}

// The first jobs are found once, in a join: a subquery in the ORDER BY ran once per row, over
// the campaign's jobs (minutes at 10k jobs).
std::string OfCampaignInOrder() {
  return " v JOIN (SELECT scenario AS order_scenario, MIN(seq) AS order_seq FROM jobs "
         "WHERE campaign_id = ?1 GROUP BY scenario) o ON o.order_scenario = v.scenario "
         "WHERE v.campaign_id = ?1 ORDER BY o.order_seq, positioner, rng_run";
}

}  // namespace rlpos
