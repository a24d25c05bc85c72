#pragma once
// Which placement a dependant gets once the job it depends on succeeds (a scheduling rule, used
// by the store's ResultRecorder inside the success's transaction): an eval takes the placement
// its train or position job produced, through its position rule (an offset or not), and a
// pending one becomes ready. The row then shows exactly what it will run, and its content is
// known, so the result cache may serve it at once.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "common/store/dependant_rule.h"

namespace rlpos {

class Database;
class ResultCache;
class Statement;
class StoreDb;

class PlacementBinding : public DependantRule {
 public:
  // `cache` is asked for the result of each dependant that the binding releases.
  PlacementBinding(StoreDb& store, ResultCache& cache);

  // Offset evals are defined for one UAV: a placement of several cannot feed them.
  void Check(const std::string& job_id, const Placement& produced) override;
  // A chunk of dependants at a time: one baseline with RngRun 1..100000 has 100k dependants,
  // never all in memory.
  void Bind(const std::string& job_id, const Placement& produced) override;

 private:
  struct Bound {
    std::string id;
    Placement placement;
    std::optional<std::string> cache_key;
    bool released = false;  // pending -> ready now
  };
  // The next chunk of dependants after rowid `after` (advanced), with their placements.
  void ReadChunk(Statement& dependants, const Placement& produced, std::int64_t& after,
                 std::vector<Bound>& bound);
  void WriteChunk(Statement& update, const std::vector<Bound>& bound);
  // Whether an eval at an offset around `job_id`'s position depends on it.
  bool HasOffsetDependants(const std::string& job_id);

  StoreDb& store_;
  Database* db_;
  ResultCache& cache_;
};

}  // namespace rlpos
