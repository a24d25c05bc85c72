#!/usr/bin/env bash
# The README's main command, read from README.md and run as written from a copy of the repository
# root: campaigns/mini.json on 2 local workers completes, every job succeeds exactly once, the
# metrics are plausible, and the report is written. Then: the train jobs' artifacts are home and an
# rl eval re-runs from an exported policy with the same numbers; the same campaign under a new name
# is served whole from the result cache (in a copy of the database).
# Usage: mini_campaign.sh BIN_DIR SOURCE_DIR [RESULTS_DIR]
# RESULTS_DIR is emptied and becomes the root's results/: the docs' pages that read a results
# database use this one (tests/docs, the CTest fixture docs_results).
source "$(dirname "$0")/lib.sh"
RESULTS=${3:-$WORK/results}
rm -rf "$RESULTS" && mkdir -p "$RESULTS"
ROOT=$WORK/root
mkdir "$ROOT"
for entry in "$SRC"/*; do
  case ${entry##*/} in build | build-* | results) ;; *) ln -s "$entry" "$ROOT/" ;; esac
done
ln -s "$BIN/.." "$ROOT/build"
ln -s "$RESULTS" "$ROOT/results"
MAIN=$(sed -n '/^```sh$/,/^```$/s/^scripts\/bootstrap && //p' "$SRC/README.md" | head -n 1)
[ -n "$MAIN" ] || fail "README.md's first block has no 'scripts/bootstrap && COMMAND'"
(cd "$ROOT" && bash -c "$MAIN") >"$WORK/out.txt" 2>"$WORK/err.txt" \
  || { cat "$WORK/err.txt" >&2; fail "the README's main command exited non-zero: $MAIN"; }
ID=$(sed -n 's/^campaign //p' "$WORK/out.txt")
[ -n "$ID" ] || fail "run printed no campaign id"
DB=$RESULTS/rlpos.db

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

REPORT=$RESULTS/reports/$ID
# A map per scenario (B, C), each with the rl flight of its train job.
for f in summary.csv summary.md throughput_ccdf.csv delay_cdf.csv learning_curves.csv map_1.png \
  map_2.png; do
  [ -s "$REPORT/$f" ] || fail "report file $f missing"
done
if /usr/bin/python3 -c 'import matplotlib' 2>/dev/null; then
  for f in throughput_ccdf_B.png delay_cdf_C.png learning_curve_B.png; do
    [ -s "$REPORT/$f" ] || fail "plot $f missing"
  done
fi
grep -q '^B  *rl ' "$WORK/out.txt" || fail "summary table has no B rl row"
expect_eq "maps with the rl flight" "$(grep -c '^The rl flight' "$REPORT/summary.md")" 2

# The read commands on the finished campaign.
"$CAMPAIGN" status "$ID" --db "$DB" >"$WORK/status.txt"
# An eval whose twin (same scenario, run and position: an offset clamped onto the rl position at
# the ceiling, say) ran before takes its result from the cache: as many as the positions repeat.
TWINS=$(sql "$DB" "SELECT COUNT(*) - COUNT(DISTINCT scenario || ' ' || rng_run || ' ' ||
  printf('%.6f %.6f %.6f', x, y, z)) FROM v_eval_runs")
FROM_CACHE=$([ "$TWINS" -gt 0 ] && echo " ($TWINS from the cache)" || true)
grep -q "jobs: 44 total, 0 pending, 0 ready, 0 running, 44 succeeded$FROM_CACHE, 0 failed" \
  "$WORK/status.txt" \
  || fail "status said ($TWINS twins): $(cat "$WORK/status.txt")"
expect_eq "cached evals" "$(sql "$DB" "SELECT COUNT(*) FROM jobs WHERE kind = 'eval' AND
  cached_from IS NOT NULL")" "$TWINS"
expect_eq "results csv rows" "$("$CAMPAIGN" results "$ID" --db "$DB" --format csv | wc -l)" 19
"$CAMPAIGN" results "$ID" --db "$DB" --format json | python3 -c 'import json,sys; json.load(sys.stdin)' \
  || fail "results json"
# Artifacts: each train job's five files, beside the database, matching their sha256.
expect_eq "artifacts" "$(sql "$DB" "SELECT COUNT(*) FROM artifacts a JOIN jobs j ON j.id = a.job_id
  WHERE j.kind = 'train'")" 10
ARTIFACTS=$RESULTS/rlpos.artifacts
while IFS='|' read -r path sha; do
  [ "$(sha256sum "$ARTIFACTS/$path" | cut -d' ' -f1)" = "$sha" ] || fail "artifact $path: sha256"
done < <(sql "$DB" "SELECT path, sha256 FROM artifacts")
# An rl eval on "another machine": from the exported policy alone, the same position and the
# same metrics as the campaign's.
"$CAMPAIGN" artifacts "$ID" --db "$DB" --out "$WORK/export" 2>/dev/null || fail "artifacts --out"
POLICY=$WORK/export/train/B/seed1
SIM=$BIN/rlpos-sim
POSITION=$("$SIM" position --scenario "$POLICY/scenario.json" --positioner rl --policy "$POLICY" \
  --json | python3 -c 'import json,sys; print(",".join(str(v) for v in json.load(sys.stdin)["position"]))')
expect_eq "rl position from the exported policy" "$POSITION" "$(sql "$DB" "SELECT x || ',' || y ||
  ',' || z FROM v_eval_runs WHERE scenario = 'B' AND positioner = 'rl' AND rng_run = 1")"
THROUGHPUT=$("$SIM" eval --scenario "$POLICY/scenario.json" --position "$POSITION" --run 1 --json \
  | python3 -c 'import json,sys; print("%.9f" % json.load(sys.stdin)["aggregate_throughput_mbps"])')
expect_eq "rl eval from the exported policy" "$THROUGHPUT" "$(sql "$DB" "SELECT printf('%.9f',
  throughput_mbps) FROM v_eval_runs WHERE scenario = 'B' AND positioner = 'rl' AND rng_run = 1")"

# The same campaign under another name: every job is served from the cache, with the same
# metrics, each row naming the job it came from.
python3 - "$SRC/campaigns/mini.json" "$WORK/again.json" <<'PY'
import json, os, sys
campaign = json.load(open(sys.argv[1]))
campaign["name"] = "mini-again"
folder = os.path.dirname(os.path.abspath(sys.argv[1]))
campaign["scenarios"] = [os.path.join(folder, s) for s in campaign["scenarios"]]
json.dump(campaign, open(sys.argv[2], "w"))
PY
# In a copy: the pages that read results/ see the README's campaign alone.
sqlite3 "$DB" ".backup '$WORK/again.db'"
cp -r "$RESULTS/rlpos.artifacts" "$WORK/again.artifacts"
DB=$WORK/again.db
START=$SECONDS
"$CAMPAIGN" run "$WORK/again.json" --workers 2 --db "$DB" --tag "$TAG" --no-progress \
  >"$WORK/again.txt" 2>"$WORK/again.err" || { cat "$WORK/again.err" >&2; fail "re-run exited $?"; }
AGAIN=$(sed -n 's/^campaign //p' "$WORK/again.txt")
[ -n "$AGAIN" ] && [ "$AGAIN" != "$ID" ] || fail "the renamed campaign has id '$AGAIN'"
expect_eq "re-run jobs not served by the cache" "$(sql "$DB" "SELECT COUNT(*) FROM jobs
  WHERE campaign_id = '$AGAIN' AND (state != 'succeeded' OR cached_from IS NULL)")" 0
"$CAMPAIGN" status "$AGAIN" --db "$DB" >"$WORK/again-status.txt"
grep -q "44 succeeded (44 from the cache), 0 failed" "$WORK/again-status.txt" \
  || fail "status of the re-run said: $(cat "$WORK/again-status.txt")"
METRICS_OF="SELECT scenario, positioner, rng_run, throughput_mbps, delay_ms FROM v_eval_runs
  WHERE campaign_id = '%s' ORDER BY 1, 2, 3"
# shellcheck disable=SC2059
expect_eq "metrics of the re-run" "$(sql "$DB" "$(printf "$METRICS_OF" "$AGAIN")")" \
  "$(sql "$DB" "$(printf "$METRICS_OF" "$ID")")"
echo "ok: mini campaign $ID; artifacts exported and replayed; renamed re-run $AGAIN served \
from the cache in $((SECONDS - START)) s"
