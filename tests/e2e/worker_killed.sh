#!/usr/bin/env bash
# A worker killed (SIGKILL) in the middle of a job: its lease runs out, the job goes back to
# the queue, the runner starts a new worker, and the campaign completes with no job lost or
# counted twice.
source "$(dirname "$0")/lib.sh"
DB=$WORK/rlpos.db
start_run "$SRC/tests/e2e/campaigns/kill.json"
# In the middle of the eval: its rlpos-sim runs under w0.
await_job_on_w0 eval "the eval"
# `status` from another terminal while it runs: jobs running.
"$CAMPAIGN" status --db "$DB" | grep -Eq "(^| )[1-9][0-9]* running" || fail "status does not show the running job"
pkill -KILL -f -- "rlpos-worker --id $TAG-w0 " || fail "could not kill worker w0"
wait "$RUN" || { cat "$WORK/err.txt" >&2; fail "run exited non-zero"; }

expect_complete "$DB" 12
expect_eq "attempt of the killed job" "$(sql "$DB" "SELECT attempt FROM jobs WHERE id = '$JOB'")" 2
expect_eq "its infrastructure losses" "$(sql "$DB" "SELECT infra_losses FROM jobs WHERE id = '$JOB'")" 1
grep -q "rlpos-worker $TAG-w0 ended (signal 9" "$WORK/err.txt" || fail "the runner did not restart w0"
expect_eq "killed worker state" "$(sql "$DB" "SELECT state FROM workers WHERE id = '$TAG-w0'")" lost
echo "ok: killed worker's job $JOB ran again"
