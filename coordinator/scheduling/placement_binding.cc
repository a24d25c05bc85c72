#include "coordinator/scheduling/placement_binding.h"

#include <nlohmann/json.hpp>
#include <stdexcept>

#include "common/campaign/job_content.h"
#include "common/job/position_rule.h"
#include "common/store/job_rows.h"
#include "common/store/result_cache.h"
#include "common/store/sqlite_db.h"
#include "common/store/store_db.h"
#include "common/store/store_error.h"

namespace rlpos {

PlacementBinding::PlacementBinding(StoreDb& store, ResultCache& cache)
    : store_(store), db_(&store.sql()), cache_(cache) {}

void PlacementBinding::Check(const std::string& job_id, const Placement& produced) {
  if (produced.size() > 1 && HasOffsetDependants(job_id)) {
    throw std::invalid_argument("a placement of " + std::to_string(produced.size()) +
                                " UAVs, but offset evals (defined for one) depend on it");
  }
}

void PlacementBinding::Bind(const std::string& job_id, const Placement& produced) {
  Statement dependants = db_->Prepare(
      "SELECT rowid, id, position_rule_json, kind, content_base, state FROM jobs "
      "WHERE depends_on = ? AND rowid > ? ORDER BY rowid LIMIT 1024");
  Statement update = db_->Prepare(
      "UPDATE jobs SET x = ?, y = ?, z = ?, positions_json = ?, cache_key = ?, "
      "content_base = NULL, "
      "state = CASE state WHEN 'pending' THEN 'ready' ELSE state END WHERE id = ?");
  std::vector<Bound> bound;
  for (std::int64_t after = 0;; bound.clear()) {
    dependants.Reset();
    dependants.Bind(job_id).Bind(after);
    ReadChunk(dependants, produced, after, bound);
    if (bound.empty())
      break;
    WriteChunk(update, bound);
    for (const auto& b : bound) {
      if (b.released && b.cache_key)
        cache_.ResolveFromCache(b.id);
    }
  }
}

void PlacementBinding::ReadChunk(Statement& dependants, const Placement& produced,
                                 std::int64_t& after, std::vector<Bound>& bound) {
  const ResultColumn rowid = dependants.Column("rowid"), job_id = dependants.Column("id"),
                     position_rule = dependants.Column("position_rule_json"),
                     kind = dependants.Column("kind"),
                     content_base = dependants.Column("content_base"),
                     state = dependants.Column("state");
  while (dependants.Step()) {
    after = dependants.Int(rowid);
    const std::string id = dependants.Text(job_id);
    PositionRule rule;
    JobKind dependant_kind;
    try {
      rule = PositionRuleFromJson(nlohmann::json::parse(dependants.Text(position_rule)));
      dependant_kind = ParseJobKind(dependants.Text(kind));
    } catch (const std::exception& e) {
      throw StoreError(store_.file(), "job " + id + ": bad position rule: " + e.what());
    }
    Placement placement = ApplyPositionRule(rule, produced);  // Check passed: cannot throw
    auto key = JobContentKey(dependants.OptionalText(content_base).value_or(""), dependant_kind,
                             placement);
    bound.push_back(
        {id, std::move(placement), std::move(key), dependants.Text(state) == "pending"});
  }
  dependants.Reset();
}

void PlacementBinding::WriteChunk(Statement& update, const std::vector<Bound>& bound) {
  for (const auto& b : bound) {
    update.Reset();
    update.Bind(b.placement.front().x)
        .Bind(b.placement.front().y)
        .Bind(b.placement.front().z)
        .Bind(PositionsJson(b.placement))
        .Bind(b.cache_key)
        .Bind(b.id)
        .Run();
  }
  update.Reset();
}

bool PlacementBinding::HasOffsetDependants(const std::string& job_id) {
  Statement select = db_->Prepare(
      "SELECT 1 FROM jobs WHERE depends_on = ? AND "
      "json_extract(position_rule_json, '$.offset') != 0 LIMIT 1");
  select.Bind(job_id);
  return select.Step();
}

}  // namespace rlpos
