#!/usr/bin/env bash
# A job whose ns-3 run aborts and one that runs past its timeout are retried, then reported
# failed with their error; the rest of the campaign completes; run exits 3.
source "$(dirname "$0")/lib.sh"
DB=$WORK/rlpos.db
set +e
"$CAMPAIGN" run "$SRC/tests/e2e/campaigns/failing.json" --workers 2 --db "$DB" --tag "$TAG" \
  --no-progress >"$WORK/out.txt" 2>"$WORK/err.txt"
CODE=$?
set -e
sqlite3 "$DB" "SELECT key, state, attempt, error FROM jobs" >&2
expect_eq "exit code" "$CODE" 3
expect_eq "B eval" "$(sql "$DB" "SELECT state FROM jobs WHERE key = 'eval/B/baseline/run1'")" succeeded
expect_eq "aborting eval" "$(sql "$DB" "SELECT state || ' ' || attempt FROM jobs
  WHERE key = 'eval/B-abort/baseline/run1'")" "failed 2"
sql "$DB" "SELECT error FROM jobs WHERE key = 'eval/B-abort/baseline/run1'" | grep -q "ns-3 aborted" \
  || fail "the abort's error does not say so"
expect_eq "hanging eval" "$(sql "$DB" "SELECT state || ' ' || attempt || ' ' || error FROM jobs
  WHERE key = 'eval/A-slow/baseline/run1'")" "failed 2 timed out after 8 s"
grep -q "failed: eval/B-abort/baseline/run1 after 2 attempt(s)" "$WORK/err.txt" \
  || fail "run did not list the failed job"
# The worker stopped the hanging rlpos-sim: nothing of the campaign is left running.
! pgrep -f -- "A-slow" >/dev/null || fail "an rlpos-sim of the timed-out job is still running"
echo "ok: abort and timeout retried, then failed with their errors"
