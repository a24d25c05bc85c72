#!/usr/bin/env bash
# The multi-machine way, on loopback: a standalone rlpos-coordinator and rlpos-worker, and
# rlpos-campaign submit, status --watch, retry and cancel talking to them over DDS.
source "$(dirname "$0")/lib.sh"
DB=$WORK/rlpos.db
DDS=(--loopback "$TAG" --domain $((1 + $$ % 200)))
mkdir -p "$WORK/logs/daemons"
"$BIN/rlpos-coordinator" --db "$DB" "${DDS[@]}" 2>"$WORK/logs/daemons/coordinator.log" &
BG_PIDS+=("$!")
"$BIN/rlpos-worker" --slots 2 --id "$TAG-w" --work-dir "$WORK/work" "${DDS[@]}" \
  2>"$WORK/logs/daemons/worker.log" &
BG_PIDS+=("$!")

# submit prints the campaign id; the same campaign again is the same id, nothing new.
ID=$("$CAMPAIGN" submit "$SRC/tests/e2e/campaigns/tiny_b.json" "${DDS[@]}" 2>"$WORK/submit.err") \
  || fail "submit: $(cat "$WORK/submit.err")"
grep -q "submitted tiny-b: 6 jobs" "$WORK/submit.err" || fail "submit said: $(cat "$WORK/submit.err")"
"$CAMPAIGN" status "$ID" --db "$DB" --watch --period 0.5 >"$WORK/status.txt" || fail "status --watch"
grep -q "finished" "$WORK/status.txt" || fail "status --watch ended before the campaign"
expect_complete "$DB" 6
AGAIN=$("$CAMPAIGN" submit "$SRC/tests/e2e/campaigns/tiny_b.json" "${DDS[@]}" 2>"$WORK/again.err")
expect_eq "id of the same campaign" "$AGAIN" "$ID"
grep -q "already submitted" "$WORK/again.err" || fail "resubmission said: $(cat "$WORK/again.err")"

# retry: a failed job gets a new attempt (and fails again here: ns-3 aborts every time).
ABORT=$("$CAMPAIGN" submit "$SRC/tests/e2e/campaigns/abort_only.json" "${DDS[@]}" 2>/dev/null)
"$CAMPAIGN" status "$ABORT" --db "$DB" --watch --period 0.5 >/dev/null
expect_eq "after one attempt" "$(sql "$DB" "SELECT state || ' ' || attempt FROM jobs
  WHERE key = 'eval/B-abort/baseline/run1'")" "failed 1"
"$CAMPAIGN" retry "$ABORT" "${DDS[@]}" 2>"$WORK/retry.err" || fail "retry: $(cat "$WORK/retry.err")"
grep -q "retrying 1 job(s)" "$WORK/retry.err" || fail "retry said: $(cat "$WORK/retry.err")"
"$CAMPAIGN" status "$ABORT" --db "$DB" --watch --period 0.5 >/dev/null
expect_eq "after retry" "$(sql "$DB" "SELECT state || ' ' || attempt FROM jobs
  WHERE key = 'eval/B-abort/baseline/run1'")" "failed 2"

# cancel: running jobs are stopped on the worker, the rest never start.
KILL=$("$CAMPAIGN" submit "$SRC/tests/e2e/campaigns/kill.json" "${DDS[@]}" 2>/dev/null)
wait_until 60 bash -c "[ \"\$(sqlite3 '$DB' \"SELECT COUNT(*) FROM jobs
  WHERE campaign_id = '$KILL' AND state = 'running'\")\" -ge 1 ]" || fail "nothing started"
"$CAMPAIGN" cancel "$KILL" "${DDS[@]}" 2>"$WORK/cancel.err" || fail "cancel: $(cat "$WORK/cancel.err")"
expect_eq "campaign state" "$(sql "$DB" "SELECT state FROM campaigns WHERE id = '$KILL'")" cancelled
expect_eq "jobs left to run" "$(sql "$DB" "SELECT COUNT(*) FROM jobs WHERE campaign_id = '$KILL'
  AND state IN ('pending', 'ready', 'running')")" 0
children_gone() { ! pgrep -f -- "$WORK/work/$KILL" >/dev/null; }
wait_until 10 children_gone || fail "the worker did not stop the cancelled jobs"
# An unknown campaign is refused by the coordinator: bad input.
set +e
"$CAMPAIGN" cancel nosuchid "${DDS[@]}" 2>"$WORK/unknown.err"
CODE=$?
set -e
expect_eq "cancel of an unknown campaign" "$CODE" 2
grep -q 'no campaign "nosuchid"' "$WORK/unknown.err" || fail "unclear: $(cat "$WORK/unknown.err")"
echo "ok: submit, status --watch, retry and cancel against standalone daemons"
