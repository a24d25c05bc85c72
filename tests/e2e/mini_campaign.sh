#!/usr/bin/env bash
# The README's main command: campaigns/mini.json on 2 local workers completes, every job
# succeeds exactly once, the metrics are plausible, and the report is written.
source "$(dirname "$0")/lib.sh"
DB=$WORK/rlpos.db
"$CAMPAIGN" run "$SRC/campaigns/mini.json" --workers 2 --db "$DB" --tag "$TAG" \
  >"$WORK/out.txt" 2>"$WORK/err.txt" || { cat "$WORK/err.txt" >&2; fail "run exited $?"; }
ID=$(sed -n 's/^campaign //p' "$WORK/out.txt")
[ -n "$ID" ] || fail "run printed no campaign id"

expect_complete "$DB" 44
# Provenance on every result: the host, this build, and the sha256 of the scenario it ran.
expect_eq "succeeded jobs without provenance" "$(sql "$DB" "SELECT COUNT(*) FROM jobs
  WHERE state = 'succeeded' AND (host IS NULL OR rlpos_version IS NULL OR ns3_version IS NULL
  OR torch_version IS NULL OR cyclonedds_version IS NULL OR length(scenario_sha256) != 64)")" 0
expect_eq "builds of the campaign" "$(sql "$DB" "SELECT COUNT(DISTINCT rlpos_version) FROM jobs")" 1
expect_eq "eval jobs" "$(sql "$DB" "SELECT COUNT(*) FROM jobs WHERE kind = 'eval'")" 36
# Plausible: throughput within what one 802.11ac UAV can carry, nLoS within 0..N, delays
# positive; the oracle's position sees every UE of B, and the RL position beats the baseline.
expect_eq "implausible rows" "$(sql "$DB" "SELECT COUNT(*) FROM v_eval_runs WHERE
  throughput_mbps <= 1 OR throughput_mbps > 1000 OR n_los < 0 OR n_los > n_ues OR
  (delay_ms IS NOT NULL AND delay_ms <= 0)")" 0
expect_eq "B oracle nLoS" "$(sql "$DB" "SELECT MIN(n_los) FROM v_eval_runs
  WHERE scenario = 'B' AND positioner = 'oracle'")" 4
expect_eq "rl above baseline in B and C" "$(sql "$DB" "SELECT COUNT(*) FROM (
  SELECT scenario, AVG(CASE WHEN positioner = 'rl' THEN throughput_mbps END) AS rl,
         AVG(CASE WHEN positioner = 'baseline' THEN throughput_mbps END) AS base
  FROM v_eval_runs GROUP BY scenario) WHERE rl > base")" 2

# Same seeds, same numbers: the positions that need no training (ns-3 and the analytic model
# only, no libtorch kernels that may differ between CPUs) give the recorded metrics exactly.
expect_eq "metrics of the fixed positions" "$(sql "$DB" "SELECT scenario, positioner, rng_run,
  printf('%.6f', throughput_mbps), printf('%.6f', delay_ms), n_los, x, y, z FROM v_eval_runs
  WHERE positioner IN ('baseline', 'centroid', 'oracle') ORDER BY 1, 2, 3" | tr '|' ' ')" \
  "$(cat "$SRC/tests/e2e/golden/mini_fixed_positions.txt")"

REPORT=$WORK/reports/$ID
for f in summary.csv summary.md throughput_ccdf.csv delay_cdf.csv; do
  [ -s "$REPORT/$f" ] || fail "report file $f missing"
done
if /usr/bin/python3 -c 'import matplotlib' 2>/dev/null; then
  for f in throughput_ccdf_B.png delay_cdf_C.png; do
    [ -s "$REPORT/$f" ] || fail "plot $f missing"
  done
fi
grep -q '^B  *rl ' "$WORK/out.txt" || fail "summary table has no B rl row"

# The read commands on the finished campaign.
"$CAMPAIGN" status "$ID" --db "$DB" >"$WORK/status.txt"
grep -q "jobs: 44 total, 0 pending, 0 ready, 0 running, 44 succeeded, 0 failed" "$WORK/status.txt" \
  || fail "status said: $(cat "$WORK/status.txt")"
expect_eq "results csv rows" "$("$CAMPAIGN" results "$ID" --db "$DB" --format csv | wc -l)" 19
"$CAMPAIGN" results "$ID" --db "$DB" --format json | python3 -c 'import json,sys; json.load(sys.stdin)' \
  || fail "results json"
echo "ok: mini campaign $ID"
