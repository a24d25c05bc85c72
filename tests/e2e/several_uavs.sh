#!/usr/bin/env bash
# A campaign of the two shipped multi-UAV scenarios: every eval runs at its placement (one
# position per UAV, the rl one as trained), each UAV's share lands in uav_metrics and adds up to
# the run's totals, offsets are left out, and the summary and report show each UAV.
source "$(dirname "$0")/lib.sh"
DB=$WORK/rlpos.db
run_campaign "$SRC/tests/e2e/campaigns/several_uavs.json"

# Per scenario: 2 positions + 1 train + 3 evals (baseline, centroid, rl; no offsets).
expect_complete "$DB" 12
expect_eq "eval labels" "$(sql "$DB" "SELECT group_concat(scenario || ':' || positioner, ' ') FROM
  (SELECT scenario, positioner FROM v_eval_runs ORDER BY scenario, positioner)")" \
  "campus2:baseline campus2:centroid campus2:rl urban3:baseline urban3:centroid urban3:rl"
expect_eq "UAV rows" "$(sql "$DB" "SELECT group_concat(scenario || ':' || n, ' ') FROM (SELECT
  scenario, COUNT(*) AS n FROM v_eval_uavs GROUP BY scenario ORDER BY scenario)")" \
  "campus2:6 urban3:9"
# Each eval's UAVs split its UEs, LoS count and throughput exactly.
expect_eq "evals whose UAVs do not add up" "$(sql "$DB" "SELECT COUNT(*) FROM v_eval_runs r JOIN
  (SELECT job_id, SUM(ues_served) AS ues, SUM(n_los) AS los, SUM(throughput_mbps) AS thr
   FROM v_eval_uavs GROUP BY job_id) u USING (job_id)
  WHERE u.ues != r.n_ues OR u.los != r.n_los OR abs(u.thr - r.throughput_mbps) > 1e-6")" "0"
# The rl evals ran at the trained placement: the train result's positions, UAV by UAV.
for s in campus2 urban3; do
  trained=$(sql "$DB" "SELECT json(json_extract(result_json, '$.positions')) FROM jobs
    WHERE key = 'train/$s/seed1'")
  bound=$(sql "$DB" "SELECT json(positions_json) FROM jobs WHERE key = 'eval/$s/rl/run1'")
  measured=$(sql "$DB" "SELECT json_group_array(json_array(x, y, z)) FROM (SELECT x, y, z FROM
    v_eval_uavs WHERE scenario = '$s' AND positioner = 'rl' ORDER BY uav)")
  [ -n "$trained" ] || fail "train/$s/seed1 returned no positions"
  expect_eq "$s rl placement bound" "$bound" "$trained"
  expect_eq "$s rl placement measured" "$measured" "$trained"
done

grep -q "^per UAV:" "$WORK/out.txt" || fail "the printed results have no per-UAV table"
grep -q "^urban3  *rl  *uav3 " "$WORK/out.txt" || fail "no per-UAV row for urban3 rl uav3: $(cat "$WORK/out.txt")"
REPORT=$WORK/reports/$ID
grep -q "| campus2 | centroid | south |" "$REPORT/summary.md" || fail "summary.md has no per-UAV row"
expect_eq "uav_summary.csv rows" "$(($(wc -l <"$REPORT/uav_summary.csv") - 1))" "15"
echo "ok: multi-UAV campaign $ID; placements bound and measured per UAV, per-UAV summary and report"
