#!/usr/bin/env bash
# The runner's own cost, with a simulator that answers at once (rlpos-standin-sim): a standalone
# coordinator and W workers x S slots on a loopback tag of their own, one campaign of N eval jobs
# (scenario B, fixed baseline position, RngRun 1..N). Runs unsecured and with --security side by
# side and prints, per mode:
#   discovery   median wall time of a fresh `rlpos-campaign cancel` until the coordinator's
#               answer (process start, participant, discovery, handshake, request and reply)
#   jobs/s      jobs / (submit to campaign finished)
#   coord ms/job  coordinator CPU (user + system) per job during the campaign
#   coord RSS   coordinator peak resident memory
#   worker ms/job  the workers' own CPU per job (their stand-in children not included)
#   worker RSS  the largest worker peak resident memory
#   DB B/job    database size per job, and without the results (result_json and the metrics
#               table with its indexes)
# Usage: scripts/bench_dispatch.sh [N_JOBS] [WORKERS] [SLOTS] [BUILD_DIR]
# RLPOS_BENCH_PERF=DIR also records the coordinator with `perf record -g` into DIR/<mode>.data.
# RLPOS_BENCH_MODES="xargs unsecured secured" (default) picks the modes; xargs runs the same
# stand-in N times with `xargs -P W*S` (no runner at all), for the ratio.
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
jobs=${1:-1000}
workers=${2:-4}
slots=${3:-4}
bin=${4:-$here/build}/bin
for tool in sqlite3 bc; do command -v "$tool" >/dev/null || { echo "needs $tool" >&2; exit 2; }; done
[ -x "$bin/rlpos-standin-sim" ] || { echo "$bin/rlpos-standin-sim: missing (build first)" >&2; exit 2; }
work=$(mktemp -d "${TMPDIR:-/tmp}/rlpos-bench-dispatch.XXXXXX")
pids=()
cleanup() {
  for pid in "${pids[@]}"; do kill "$pid" 2>/dev/null || true; done
  wait 2>/dev/null || true
  rm -rf "$work"
}
trap cleanup EXIT
ticks=$(getconf CLK_TCK)

cpu_ticks() { awk '{print $14 + $15}' "/proc/$1/stat"; }
median() { sort -n | awk '{v[NR] = $1} END {print v[int((NR + 1) / 2)]}'; }

cat >"$work/campaign.json" <<JSON
{"name": "bench-dispatch", "scenarios": ["$here/campaigns/scenarios/b.json"],
 "rng_runs": [1, $jobs], "positioners": ["baseline"],
 "eval": {"duration": 1, "warmup": 0.5}, "retries": 0, "job_timeout_s": 600}
JSON

run_mode() {  # run_mode NAME [SECURITY FLAGS...]
  local name=$1
  shift
  local dir=$work/$name
  mkdir -p "$dir"
  local dds=(--loopback "rlpos-bench-$$-$name" --domain $((1 + ($$ + ${#name}) % 200)) "$@")
  "$bin/rlpos-coordinator" --db "$dir/rlpos.db" --log-level warning "${dds[@]}" \
    2>"$dir/coordinator.log" &
  local coordinator=$!
  pids+=("$coordinator")
  # Discovery: 5 fresh clients, each until the coordinator's answer ("no campaign": exit 2).
  local samples=()
  for i in 1 2 3 4 5; do
    local t0 t1 code=0
    t0=$(date +%s.%N)
    "$bin/rlpos-campaign" cancel nosuchcampaign "${dds[@]}" --timeout 20 2>/dev/null || code=$?
    t1=$(date +%s.%N)
    [ "$code" -eq 2 ] || { echo "$name: the coordinator did not answer (exit $code)" >&2; exit 1; }
    samples+=("$(echo "$t1 - $t0" | bc)")
  done
  local discovery worker_pids=()
  discovery=$(printf '%s\n' "${samples[@]}" | median)
  for w in $(seq 1 "$workers"); do
    "$bin/rlpos-worker" --id "$name-w$w" --slots "$slots" --work-dir "$dir/work-$w" \
      --sim "$bin/rlpos-standin-sim" --log-level warning "${dds[@]}" 2>"$dir/worker-$w.log" &
    pids+=("$!")
    worker_pids+=("$!")
  done
  local cpu0 t0 id wcpu0=0
  cpu0=$(cpu_ticks "$coordinator")
  for pid in "${worker_pids[@]}"; do wcpu0=$((wcpu0 + $(cpu_ticks "$pid"))); done
  t0=$(date +%s.%N)
  local perf=""
  if [ -n "${RLPOS_BENCH_PERF:-}" ]; then
    mkdir -p "$RLPOS_BENCH_PERF"
    perf record -q -F 499 -g -p "$coordinator" -o "$RLPOS_BENCH_PERF/$name.data" 2>/dev/null &
    perf=$!
  fi
  id=$("$bin/rlpos-campaign" submit "$work/campaign.json" "${dds[@]}" --timeout 120 2>/dev/null)
  until [ "$(sqlite3 "$dir/rlpos.db" "SELECT state FROM campaigns WHERE id = '$id'")" = finished ]; do
    kill -0 "$coordinator" 2>/dev/null || { echo "$name: the coordinator died" >&2; exit 1; }
    sleep 0.2
  done
  local t1 cpu1 total failed rss db_bytes wcpu1=0 wrss=0 result_bytes
  t1=$(date +%s.%N)
  cpu1=$(cpu_ticks "$coordinator")
  for pid in "${worker_pids[@]}"; do
    wcpu1=$((wcpu1 + $(cpu_ticks "$pid")))
    local r
    r=$(awk '/VmHWM/ {print $2}' "/proc/$pid/status")
    [ "$r" -gt "$wrss" ] && wrss=$r
  done
  if [ -n "$perf" ]; then kill -INT "$perf"; wait "$perf" || true; fi
  total=$(sqlite3 "$dir/rlpos.db" "SELECT COUNT(*) FROM jobs WHERE campaign_id = '$id'")
  failed=$(sqlite3 "$dir/rlpos.db" "SELECT COUNT(*) FROM jobs WHERE state != 'succeeded'")
  [ "$failed" -eq 0 ] || { echo "$name: $failed job(s) did not succeed" >&2; exit 1; }
  rss=$(awk '/VmHWM/ {print $2}' "/proc/$coordinator/status")
  sqlite3 "$dir/rlpos.db" "PRAGMA wal_checkpoint(TRUNCATE)" >/dev/null
  db_bytes=$(stat -c %s "$dir/rlpos.db")
  result_bytes=$(sqlite3 "$dir/rlpos.db" "SELECT (SELECT SUM(length(result_json)) FROM jobs) +
    (SELECT SUM(pgsize) FROM dbstat WHERE name IN ('metrics', 'sqlite_autoindex_metrics_1',
    'metrics_by_campaign'))")
  printf '| %s | %.3f s | %d | %.0f | %.2f | %.0f MiB | %.2f | %.0f MiB | %.0f (%.0f) |\n' \
    "$name" "$discovery" "$total" \
    "$(echo "$total / ($t1 - $t0)" | bc -l)" \
    "$(echo "($cpu1 - $cpu0) * 1000 / $ticks / $total" | bc -l)" \
    "$(echo "$rss / 1024" | bc -l)" \
    "$(echo "($wcpu1 - $wcpu0) * 1000 / $ticks / $total" | bc -l)" \
    "$(echo "$wrss / 1024" | bc -l)" \
    "$(echo "$db_bytes / $total" | bc -l)" "$(echo "($db_bytes - $result_bytes) / $total" | bc -l)"
  for pid in "${pids[@]}"; do kill "$pid" 2>/dev/null || true; done
  wait 2>/dev/null || true
  pids=()
}

"$bin/rlpos-campaign" security init "$work/sec" >/dev/null
echo "bench_dispatch: $jobs eval jobs (+1 position), $workers workers x $slots slots, loopback, $(nproc) cores"
echo "| mode | discovery | jobs | jobs/s | coord CPU ms/job | coord peak RSS | worker CPU ms/job | worker peak RSS | DB B/job (without results) |"
echo "|---|---|---|---|---|---|---|---|---|"
run_xargs() {
  mkdir -p "$work/xargs"
  python3 -c "import json,sys; d=json.load(open(sys.argv[1])); json.dump(d, open(sys.argv[2],'w'))" \
    "$here/campaigns/scenarios/b.json" "$work/xargs/scenario.json"
  local t0 t1
  t0=$(date +%s.%N)
  seq "$jobs" | xargs -P $((workers * slots)) -I{} "$bin/rlpos-standin-sim" eval \
    --scenario "$work/xargs/scenario.json" --position 50,50,25 --json --no-progress >/dev/null
  t1=$(date +%s.%N)
  printf '| xargs -P %d | - | %d | %.0f | - | - | - | - | - |\n' $((workers * slots)) "$jobs" \
    "$(echo "$jobs / ($t1 - $t0)" | bc -l)"
}

for mode in ${RLPOS_BENCH_MODES:-xargs unsecured secured}; do
  case $mode in
    xargs) run_xargs ;;
    unsecured) run_mode unsecured ;;
    secured) run_mode secured --security "$work/sec" ;;
    *) echo "unknown mode $mode" >&2; exit 2 ;;
  esac
done
