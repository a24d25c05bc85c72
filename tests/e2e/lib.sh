# Shared by the end-to-end scripts: paths, a private temporary folder, and checks.
# Usage in a script: source lib.sh BIN_DIR SOURCE_DIR
set -euo pipefail
BIN=$(cd "$1" && pwd)
SRC=$(cd "$2" && pwd)
CAMPAIGN=$BIN/rlpos-campaign
WORK=$(mktemp -d "${TMPDIR:-/tmp}/rlpos-e2e.XXXXXX")
# Each run gets its own DDS discovery tag; runs always stay on loopback.
TAG=rlpos-e2e-$$-$RANDOM
BG_PIDS=()
cleanup() {
  for pid in "${BG_PIDS[@]}"; do kill "$pid" 2>/dev/null || true; done
  wait 2>/dev/null || true
  rm -rf "$WORK"
}
trap cleanup EXIT

fail() {
  echo "FAIL: $*" >&2
  for log in "$WORK"/logs/*/*.log; do
    [ -f "$log" ] && { echo "--- $log" >&2; tail -n 20 "$log" >&2; }
  done
  exit 1
}

sql() { sqlite3 "$1" "$2"; }

expect_eq() {  # expect_eq WHAT ACTUAL EXPECTED
  [ "$2" = "$3" ] || fail "$1: got '$2', expected '$3'"
}

# wait_until SECONDS COMMAND...: polls the command every 0.5 s.
wait_until() {
  local limit=$1
  shift
  local deadline=$((SECONDS + limit))
  until "$@"; do
    [ $SECONDS -lt $deadline ] || return 1
    sleep 0.5
  done
}

# Every job succeeded, and each eval job has exactly one metrics row.
expect_complete() {  # expect_complete DB TOTAL_JOBS
  local db=$1
  expect_eq "jobs" "$(sql "$db" "SELECT COUNT(*) FROM jobs")" "$2"
  expect_eq "jobs not succeeded" "$(sql "$db" "SELECT COUNT(*) FROM jobs WHERE state != 'succeeded'")" 0
  expect_eq "eval jobs without exactly one metrics row" "$(sql "$db" \
    "SELECT COUNT(*) FROM jobs j WHERE j.kind = 'eval' AND
       (SELECT COUNT(*) FROM metrics m WHERE m.job_id = j.id) != 1")" 0
  expect_eq "metrics rows of non-eval jobs" "$(sql "$db" \
    "SELECT COUNT(*) FROM metrics m JOIN jobs j ON j.id = m.job_id WHERE j.kind != 'eval'")" 0
}

# Starts `rlpos-campaign run CAMPAIGN` on 2 workers in the background, on $DB and $TAG, with its
# output in $WORK/out.txt and $WORK/err.txt; its pid in RUN.
start_run() {  # start_run CAMPAIGN_FILE
  "$CAMPAIGN" run "$1" --workers 2 --db "$DB" --tag "$TAG" --no-progress \
    >"$WORK/out.txt" 2>"$WORK/err.txt" &
  RUN=$!
  BG_PIDS+=("$RUN")
}

# Runs `rlpos-campaign run CAMPAIGN` on 2 workers to its end, on $DB and $TAG (EXTRA after them),
# with its output in $WORK/out.txt and $WORK/err.txt; the campaign's id in ID.
run_campaign() {  # run_campaign CAMPAIGN_FILE [EXTRA...]
  "$CAMPAIGN" run "$1" --workers 2 --db "$DB" --tag "$TAG" "${@:2}" \
    >"$WORK/out.txt" 2>"$WORK/err.txt" || { rc=$?; cat "$WORK/err.txt" >&2; fail "run exited $rc"; }
  ID=$(sed -n 's/^campaign //p' "$WORK/out.txt")
  [ -n "$ID" ] || fail "run printed no campaign id"
}

# Whether worker w0 runs a KIND job now; with CHECK_RUN set, fails first if the run ($RUN) ended.
job_running_on_w0() {  # job_running_on_w0 KIND [CHECK_RUN]
  if [ -n "${2:-}" ]; then
    kill -0 "$RUN" 2>/dev/null || fail "the run exited before a $1 job ran: $(cat "$WORK/err.txt")"
  fi
  [ -f "$DB" ] && [ "$(sql "$DB" "SELECT COUNT(*) FROM jobs WHERE state = 'running'
    AND kind = '$1' AND worker_id = '$TAG-w0'" 2>/dev/null)" = 1 ]
}

sim_running_under_w0() { pgrep -P "$W0" -f -- "rlpos-sim $1" >/dev/null; }

# Waits until worker w0 runs a KIND job (its id in JOB) and the job's `rlpos-sim KIND` runs under
# it (the worker's pid in W0), for a test that then kills w0. WHAT names the run in the failure.
await_job_on_w0() {  # await_job_on_w0 KIND WHAT [CHECK_RUN]
  wait_until 240 job_running_on_w0 "$1" "${3:-}" || fail "no $1 job ever ran on worker w0"
  JOB=$(sql "$DB" "SELECT id FROM jobs WHERE state = 'running' AND worker_id = '$TAG-w0'")
  W0=$(pgrep -f -- "rlpos-worker --id $TAG-w0 ") || fail "no process for worker w0"
  wait_until 60 sim_running_under_w0 "$1" || fail "$2 never started on w0"
}

# Skips the script (77) where headless Chromium, its driver, or Selenium for $PYTHON is missing.
require_browser() {
  local tool
  for tool in chromium chromedriver; do
    command -v "$tool" >/dev/null || { echo "SKIP: $tool is not installed" >&2; exit 77; }
  done
  "$PYTHON" -c 'import selenium' 2>/dev/null || { echo "SKIP: python3-selenium is not installed" >&2; exit 77; }
}

# A browser test's start: its screenshots' folder OUT (OUTPUT_DIR, else $WORK), PYTHON and DB;
# skips (77) without a browser.
start_browser_test() {  # start_browser_test [OUTPUT_DIR]
  OUT=${1:-$WORK}
  PYTHON=/usr/bin/python3
  require_browser
  mkdir -p "$OUT"
  DB=$WORK/rlpos.db
}
