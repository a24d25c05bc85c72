#include "common/store/metric_columns.h"

#include <map>
#include <stdexcept>

#include "common/metrics/eval_metrics.h"
#include "common/store/store_error.h"

namespace rlpos {
namespace {

// Appends `columns` (", m.a AS b, ...") to the select list of the view `name`, which must end
// with "\nFROM <table>".
void ExtendView(Database& db, const std::string& name, const std::string& columns) {
  Statement select = db.Prepare("SELECT sql FROM sqlite_master WHERE type = 'view' AND name = ?");
  select.Bind(name);
  if (!select.Step())
    throw StoreError(db.file(), "has no view " + name);
  std::string sql = select.Text(select.Column("sql"));
  select.Reset();
  const std::size_t from = sql.rfind("\nFROM ");
  if (from == std::string::npos)
    throw StoreError(db.file(), "view " + name + " has no \"FROM\" line");
  sql.insert(from, columns);
  db.Exec("DROP VIEW " + name);
  db.Exec(sql);
}

std::string ViewColumn(const std::string& table, const std::string& column,
                       const std::string& view) {
  return ", " + table + "." + column + (view == column ? "" : " AS " + view);
}

void AddColumns(Database& db, const std::vector<MetricColumn>& columns) {
  std::string run_view, uav_view;
  for (const auto& c : columns) {
    db.Exec("ALTER TABLE metrics ADD COLUMN " + c.run_column + " " + c.type);
    run_view += ViewColumn("m", c.run_column, c.run_view);
    if (c.uav_column.empty())
      continue;
    db.Exec("ALTER TABLE uav_metrics ADD COLUMN " + c.uav_column + " " + c.type);
    uav_view += ViewColumn("u", c.uav_column, c.uav_view);
  }
  ExtendView(db, "v_eval_runs", run_view);
  if (!uav_view.empty())
    ExtendView(db, "v_eval_uavs", uav_view);
}

}  // namespace

Migration AddMetricColumns(int version, std::vector<MetricColumn> columns) {
  return {version, "", [columns = std::move(columns)](Database& db) { AddColumns(db, columns); }};
}

std::vector<Migration> DerivedMetricMigrations() {
  std::map<int, std::vector<MetricColumn>> by_version;
  for (const auto& m : kEvalMetrics) {
    if (m.since_schema <= kLastHandWrittenSchema)
      continue;
    if (!m.nullable)
      throw std::logic_error(std::string("metric ") + m.key +
                             " must be nullable: old rows lack it");
    by_version[m.since_schema].push_back({m.SqlType(), m.key, m.RunView(),
                                          m.HasUav() ? m.uav_key : "",
                                          m.HasUav() ? m.UavView() : ""});
  }
  std::vector<Migration> out;
  int expected = kLastHandWrittenSchema + 1;
  const auto hand_written = [](int version) {
    for (const int v : kHandWrittenSchemasAfterMetrics) {
      if (v == version)
        return true;
    }
    return false;
  };
  for (auto& [version, columns] : by_version) {
    while (hand_written(expected))
      ++expected;
    if (version != expected++)
      throw std::logic_error("metric schema versions must follow " +
                             std::to_string(kLastHandWrittenSchema) + " without a gap");
    out.push_back(AddMetricColumns(version, std::move(columns)));
  }
  return out;
}

}  // namespace rlpos
