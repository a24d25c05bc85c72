#!/usr/bin/env bash
# Track runs in a campaign, at packet level: a "track" section on a generated campus whose four
# UEs walk, the shipped policy for any scenario among its positioners (as campaigns/mobility.json). A worker killed (SIGKILL) in the middle of a track run: the job runs again and the
# campaign completes. The same campaign run again into another store, without the result cache,
# gives the same series, interval by interval, the retried run's included. `results --track`
# and the report have one row per positioner, averaged over the RngRuns.
source "$(dirname "$0")/lib.sh" "$1" "$2"
SIM=$BIN/rlpos-sim
DB=$WORK/rlpos.db
"$SIM" generate --seed 4 --style campus --ues 4 --mobility random_waypoint --out "$WORK/walk.json" \
  || fail "generate"
cat >"$WORK/track.json" <<JSON
{
  "name": "track-e2e",
  "scenarios": [{"file": "walk.json", "set": ["env.decision_interval=0.5"]}],
  "rng_runs": [1, 2],
  "positioners": [],
  "track": {"positioners": ["centroid", "oracle-track",
                          {"rl": {"policy": "$SRC/policies/generalist-1uav", "name": "generalist"}}],
            "duration": 3, "fidelity": "packet"},
  "retries": 2,
  "job_timeout_s": 300
}
JSON
start_run "$WORK/track.json"
await_job_on_w0 track "the track run" check-run
pkill -KILL -f -- "rlpos-worker --id $TAG-w0 " || fail "could not kill worker w0"
wait "$RUN" || { cat "$WORK/err.txt" >&2; fail "run exited non-zero"; }

expect_complete "$DB" 6
expect_eq "attempt of the killed job" "$(sql "$DB" "SELECT attempt FROM jobs WHERE id = '$JOB'")" 2
expect_eq "track runs, intervals" "$(sql "$DB" "SELECT COUNT(*), SUM(intervals) FROM track_runs")" \
  "6|36"
expect_eq "intervals stored" "$(sql "$DB" "SELECT COUNT(*) FROM track_intervals")" 36
# The warm-up (1 s) leaves 4 of the 6 half-second intervals scored.
expect_eq "scored intervals per run" "$(sql "$DB" \
  "SELECT DISTINCT scored_intervals FROM track_runs")" 4

SERIES="SELECT positioner, rng_run, interval, time_s, scored, reward, throughput_mbps, delay_ms,
  los_share, demands_met_share, positions_json FROM v_track_intervals
  ORDER BY positioner, rng_run, interval"
"$CAMPAIGN" run "$WORK/track.json" --workers 2 --db "$WORK/again.db" --tag "$TAG-again" \
  --no-progress --no-cache >"$WORK/again.out" 2>"$WORK/again.err" \
  || { cat "$WORK/again.err" >&2; fail "the second run failed"; }
[ "$(sql "$DB" "$SERIES")" = "$(sql "$WORK/again.db" "$SERIES")" ] \
  || fail "the same campaign gave other series (the killed job's retry included)"
expect_eq "cached results in the second store" "$(sql "$WORK/again.db" \
  "SELECT COUNT(*) FROM jobs WHERE cached_from IS NOT NULL")" 0

ID=$(sql "$DB" "SELECT id FROM campaigns")
"$CAMPAIGN" results "$ID" --db "$DB" --track --format json >"$WORK/results.json" \
  || fail "results --track"
expect_eq "results --track rows" "$(python3 -c "
import json, sys
rows = json.load(open(sys.argv[1]))
print([(r['positioner'], r['runs'], r['fidelity']) for r in rows])
" "$WORK/results.json")" "[('centroid', 2, 'packet'), ('oracle-track', 2, 'packet'), ('rl+generalist', 2, 'packet')]"
# The mean over the RngRuns is the runs' own, as stored.
expect_eq "oracle-track's mean reward" "$(python3 -c "
import json, sys
print(round([r for r in json.load(open(sys.argv[1])) if r['positioner'] == 'oracle-track'][0]
            ['mean_reward'], 9))
" "$WORK/results.json")" "$(sql "$DB" "SELECT ROUND(AVG(mean_reward), 9) FROM track_runs
  WHERE label = 'oracle-track'")"
# The report lists them: a CSV row per positioner and a section in summary.md.
"$CAMPAIGN" report "$ID" --db "$DB" --out "$WORK/report" >/dev/null || fail "report"
expect_eq "report: track_summary.csv rows" "$(tail -n +2 "$WORK/report/track_summary.csv" | cut -d, -f2 | tr '\n' ' ')" \
  "centroid oracle-track rl+generalist "
grep -q "^## Track runs" "$WORK/report/summary.md" || fail "summary.md has no track section"
# Its time series: each interval of each positioner averaged over the two runs, as SQLite has it.
expect_eq "report: track_series.csv against the store" "$(python3 -c "
import csv, sqlite3, sys
rows = [(r['positioner'], int(r['interval']), int(r['runs']), float(r['reward']))
        for r in csv.DictReader(open(sys.argv[1]))]
stored = sqlite3.connect(sys.argv[2]).execute(
    'SELECT positioner, interval, COUNT(*), AVG(reward) FROM v_track_intervals '
    'GROUP BY positioner, interval ORDER BY positioner, interval').fetchall()
same = len(rows) == len(stored) and all(
    a[:3] == b[:3] and abs(a[3] - b[3]) <= 1e-9 for a, b in zip(rows, stored))
print(len(rows), 'rows,', 'as stored' if same else 'not as stored')
" "$WORK/report/track_series.csv" "$DB")" "18 rows, as stored"
# Its figures, where matplotlib is.
if /usr/bin/python3 -c 'import matplotlib' 2>/dev/null; then
  for figure in track_distributions track_series; do
    [ "$(ls "$WORK/report/${figure}_"*.png 2>/dev/null | wc -l)" = 1 ] || fail "no ${figure} PNG"
  done
fi
echo "ok: track runs at packet level in a campaign, a killed one retried, the same series twice"
