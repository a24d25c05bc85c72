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
