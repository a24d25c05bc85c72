#pragma once
// The result cache: jobs of the same content (campaign/job_content.h) give the same result, so a
// job takes a succeeded one's result instead of running, and identical jobs that would run at
// once run once. It works inside its callers' transactions (the ledger's, the recorder's).
#include <string>

namespace rlpos {

class Database;
class ResultRecorder;
class StoreDb;

class ResultCache {
 public:
  explicit ResultCache(StoreDb& store);
  // The recorder that settles a served job as it settles a worker's result; set once, by
  // whoever puts the store's pieces together, before the first job is served.
  void SettleWith(ResultRecorder& recorder) { recorder_ = &recorder; }

  // A ready job whose content is known takes the result of a succeeded job of the same content,
  // or waits for an identical ready or running one (cache_twin), unless its campaign was
  // submitted with --no-cache.
  void ResolveFromCache(const std::string& job_id);
  // Serves the jobs that waited for `job_id`, which just succeeded.
  void ServeWaiting(const std::string& job_id);

 private:
  // Settles a ready job with the result (and artifacts) of the succeeded job `source`.
  void ServeFrom(const std::string& job_id, int attempt, const std::string& source);

  StoreDb& store_;
  Database* db_;
  ResultRecorder* recorder_ = nullptr;
};

}  // namespace rlpos
