#pragma once
// The columns that name a succeeded run in the store's views of runs (v_eval_runs, v_eval_uavs,
// v_track_runs), read alike into each view's row.
#include "common/store/sqlite_db.h"

namespace rlpos {

struct RunKeyColumns {
  explicit RunKeyColumns(const Statement& select)
      : job_id(select.Column("job_id")),
        scenario(select.Column("scenario")),
        label(select.Column("positioner")),
        rng_run(select.Column("rng_run")) {}

  // Row: one with job_id, scenario, label (the positioner) and rng_run.
  template <typename Row>
  void Read(const Statement& select, Row& row) const {
    row.job_id = select.Text(job_id);
    row.scenario = select.Text(scenario);
    row.label = select.Text(label);
    row.rng_run = select.Int(rng_run);
  }

  ResultColumn job_id, scenario, label, rng_run;
};

}  // namespace rlpos
