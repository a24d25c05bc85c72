#!/usr/bin/env bash
# The coordinator killed (SIGKILL) mid-campaign: the runner restarts it, it takes its state back
# from the database, accepts the results of jobs that ran on while it was away, and the
# campaign completes with nothing lost or doubled.
source "$(dirname "$0")/lib.sh"
DB=$WORK/rlpos.db
start_run "$SRC/tests/e2e/campaigns/kill.json"
mid_campaign() {
  [ -f "$DB" ] && [ "$(sql "$DB" "SELECT COUNT(*) >= 3 AND SUM(state = 'running') >= 1
    FROM jobs" 2>/dev/null)" = 1 ] && \
  [ "$(sql "$DB" "SELECT COUNT(*) FROM jobs WHERE state = 'succeeded'" 2>/dev/null)" -ge 3 ]
}
wait_until 240 mid_campaign || fail "the campaign never got going"
pkill -KILL -f -- "rlpos-coordinator .*--loopback $TAG" || fail "could not kill the coordinator"
wait "$RUN" || { cat "$WORK/err.txt" >&2; fail "run exited non-zero"; }

expect_complete "$DB" 12
grep -q "rlpos-coordinator ended (signal 9" "$WORK/err.txt" || fail "the coordinator was not restarted"
# Jobs that were running on live workers kept their attempt: their results were accepted.
expect_eq "jobs needing a second attempt" "$(sql "$DB" "SELECT COUNT(*) FROM jobs WHERE attempt > 1")" 0
echo "ok: coordinator restarted, nothing lost or doubled"
