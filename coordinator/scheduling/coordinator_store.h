#pragma once
// The store's pieces over one database, put together as the coordinator writes it: the ledger,
// the recorder and the cache call one another inside one transaction (a success releases
// dependants that the cache may serve, which records their success in turn), and the dependants'
// placements follow the scheduling rule of PlacementBinding. Callers use the pieces directly:
// store.ledger.Submit(plan), store.recorder.RecordSuccess(...), store.reader.Progress(id).
#include <string>

#include "common/store/job_ledger.h"
#include "common/store/result_cache.h"
#include "common/store/result_recorder.h"
#include "common/store/results_reader.h"
#include "common/store/store_db.h"
#include "coordinator/scheduling/placement_binding.h"

namespace rlpos {

struct CoordinatorStore {
  // Opens or creates the file and migrates it (StoreDb). Throws StoreError naming the file.
  explicit CoordinatorStore(const std::string& file, StoreOptions options = {})
      : db(file, std::move(options)),
        cache(db),
        ledger(db, cache),
        binding(db, cache),
        recorder(db, ledger, cache, binding),
        reader(db) {
    cache.SettleWith(recorder);
  }
  CoordinatorStore(const CoordinatorStore&) = delete;
  CoordinatorStore& operator=(const CoordinatorStore&) = delete;

  StoreDb db;
  ResultCache cache;
  JobLedger ledger;
  PlacementBinding binding;
  ResultRecorder recorder;
  ResultsReader reader;
};

}  // namespace rlpos
