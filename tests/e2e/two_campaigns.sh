#!/usr/bin/env bash
# Two embedded campaigns started at once on one machine: each completes with only its own jobs
# and its own workers; a second coordinator on a database in use is refused with a clear error.
source "$(dirname "$0")/lib.sh"
"$CAMPAIGN" run "$SRC/tests/e2e/campaigns/tiny_b.json" --workers 1 --db "$WORK/b/rlpos.db" \
  --tag "$TAG-b" --no-progress >"$WORK/b.out" 2>"$WORK/b.err" &
B=$!
"$CAMPAIGN" run "$SRC/tests/e2e/campaigns/tiny_c.json" --workers 1 --db "$WORK/c/rlpos.db" \
  --tag "$TAG-c" --no-progress >"$WORK/c.out" 2>"$WORK/c.err" &
C=$!
BG_PIDS+=("$B" "$C")
# Once c's coordinator holds its database (the lock next to it), a second run on it must refuse.
c_locked() { [ -f "$WORK/c/rlpos.db.coordinator.lock" ] && ! flock -n "$WORK/c/rlpos.db.coordinator.lock" true; }
wait_until 60 c_locked || fail "campaign c's coordinator never took its database"
set +e
"$CAMPAIGN" run "$SRC/tests/e2e/campaigns/tiny_c.json" --workers 1 --db "$WORK/c/rlpos.db" \
  --no-progress >/dev/null 2>"$WORK/busy.err"
CODE=$?
set -e
expect_eq "run on a database in use" "$CODE" 2
grep -q "is in use by another coordinator" "$WORK/busy.err" || fail "unclear error: $(cat "$WORK/busy.err")"
wait "$B" || { cat "$WORK/b.err" >&2; fail "campaign b failed"; }
wait "$C" || { cat "$WORK/c.err" >&2; fail "campaign c failed"; }
for x in b c; do
  DB=$WORK/$x/rlpos.db
  expect_complete "$DB" 6
  expect_eq "campaigns in $x" "$(sql "$DB" "SELECT group_concat(name) FROM campaigns")" "tiny-$x"
  expect_eq "foreign workers in $x" "$(sql "$DB" "SELECT COUNT(*) FROM workers
    WHERE id NOT LIKE '$TAG-$x-%'")" 0
  expect_eq "jobs run by foreign workers in $x" "$(sql "$DB" "SELECT COUNT(*) FROM jobs
    WHERE worker_id NOT LIKE '$TAG-$x-%'")" 0
done
echo "ok: two campaigns at once stayed apart"
