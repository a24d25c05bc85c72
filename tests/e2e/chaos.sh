#!/usr/bin/env bash
# Chaos: while `rlpos-campaign run` works on a campaign, SIGKILLs land on its workers and its
# coordinator at random (fixed seed), one after another, each once the previous victim has been
# replaced and one more job has succeeded. `retries` is 0: a job lost with its worker must come
# back without using it. Expected: the run ends well, every job succeeded exactly once, and the
# metrics equal the recorded ones of an undisturbed run (tests/e2e/golden/).
# CI runs 6 worker and 3 coordinator kills on chaos_fixed.json (its metrics are recorded in
# golden/). scripts/chaos_campaign.sh runs the long version: 20 and 10 kills on chaos_long.json,
# compared with an undisturbed run of it made first.
source "$(dirname "$0")/lib.sh"
WORKER_KILLS=${RLPOS_CHAOS_WORKER_KILLS:-6}
COORDINATOR_KILLS=${RLPOS_CHAOS_COORDINATOR_KILLS:-3}
CAMPAIGN_FILE=${RLPOS_CHAOS_CAMPAIGN:-$SRC/tests/e2e/campaigns/chaos_fixed.json}
DB=$WORK/rlpos.db
METRICS="SELECT scenario, positioner, rng_run, printf('%.6f', throughput_mbps),
  printf('%.6f', delay_ms), n_los, x, y, z FROM v_eval_runs ORDER BY 1, 2, 3"
if [ -n "${RLPOS_CHAOS_CAMPAIGN:-}" ]; then
  # Another campaign: its undisturbed metrics come from a run of it, now.
  "$CAMPAIGN" run "$CAMPAIGN_FILE" --workers 2 --db "$WORK/calm/calm.db" --tag "$TAG-calm" \
    --no-progress >/dev/null 2>"$WORK/calm.err" || fail "undisturbed run: $(tail -3 "$WORK/calm.err")"
  EXPECTED=$(sql "$WORK/calm/calm.db" "$METRICS" | tr '|' ' ')
else
  EXPECTED=$(grep -E ' (baseline|centroid|oracle) ' "$SRC/tests/e2e/golden/mini_fixed_positions.txt")
fi
# The campaign's own size, from its file (not from the database the run fills).
TOTAL=$("$CAMPAIGN" run "$CAMPAIGN_FILE" --dry-run | sed -n 's/^campaign [0-9a-f]* (.*): \([0-9]*\) jobs,.*/\1/p')
[ -n "$TOTAL" ] || fail "no job count in the dry run of $CAMPAIGN_FILE"
RANDOM=20261123
start_run "$CAMPAIGN_FILE"

succeeded() { sql "$DB" "SELECT COUNT(*) FROM jobs WHERE state = 'succeeded'" 2>/dev/null || echo 0; }
daemon_pids() {  # daemon_pids coordinator|worker: the run's live daemons of that kind
  pgrep -f -- "rlpos-$1 .*--loopback $TAG( |$)" || true
}
wait_until 120 bash -c "[ -f '$DB' ] && [ \"\$(sqlite3 '$DB' \"SELECT COUNT(*) FROM jobs
  WHERE state = 'running'\" 2>/dev/null)\" -ge 1 ]" || fail "nothing started"

left_w=$WORKER_KILLS
left_c=$COORDINATOR_KILLS
sent=0
restarts_w=0  # kills followed by a new daemon of that kind (the last may end the run instead)
restarts_c=0
while [ $((left_w + left_c)) -gt 0 ] && kill -0 "$RUN" 2>/dev/null; do
  if [ $((RANDOM % (left_w + left_c))) -lt "$left_c" ]; then kind=coordinator; else kind=worker; fi
  mapfile -t pids < <(daemon_pids "$kind")
  [ "${#pids[@]}" -gt 0 ] || { wait_until 20 bash -c "pgrep -f -- 'rlpos-$kind .*$TAG' >/dev/null"; continue; }
  victim=${pids[$((RANDOM % ${#pids[@]}))]}
  done_before=$(succeeded)
  kill -KILL "$victim" 2>/dev/null || continue
  sent=$((sent + 1))
  if [ "$kind" = coordinator ]; then left_c=$((left_c - 1)); else left_w=$((left_w - 1)); fi
  # Pace: the victim replaced (a daemon of its kind that was not there before the kill: the
  # other worker does not count), and the campaign moved on by one job (or ended).
  new_daemon() { daemon_pids "$kind" | grep -vxF -f <(printf '%s\n' "${pids[@]}") >/dev/null; }
  replaced() { new_daemon || ! kill -0 "$RUN" 2>/dev/null; }
  moved_on() { [ "$(succeeded)" -gt "$done_before" ] || ! kill -0 "$RUN" 2>/dev/null; }
  wait_until 60 replaced || fail "the $kind killed (pid $victim) was not replaced"
  if new_daemon; then
    if [ "$kind" = coordinator ]; then restarts_c=$((restarts_c + 1)); else restarts_w=$((restarts_w + 1)); fi
  fi
  wait_until 300 moved_on || fail "no job succeeded after kill $sent"
done
wait "$RUN" || { tail -5 "$WORK/err.txt" >&2; fail "run exited non-zero"; }
[ $((left_w + left_c)) -eq 0 ] || fail "the campaign ended after $sent kills, before all \
$((WORKER_KILLS + COORDINATOR_KILLS)) landed: use a longer campaign"

expect_complete "$DB" "$TOTAL"
expect_eq "jobs that used a retry" "$(sql "$DB" "SELECT COUNT(*) FROM jobs
  WHERE attempt - infra_losses > 1")" 0
# The runner said so for each daemon it restarted: each kind at least as often as a new daemon
# of that kind was seen after a kill, at most as often as that kind was killed.
for kind in worker coordinator; do
  reported=$(grep -c "^rlpos-campaign: rlpos-$kind .*; restarted (" "$WORK/err.txt" || true)
  if [ $kind = worker ]; then seen=$restarts_w killed=$WORKER_KILLS; else seen=$restarts_c killed=$COORDINATOR_KILLS; fi
  [ "$reported" -ge "$seen" ] && [ "$reported" -le "$killed" ] \
    || fail "the runner reported $reported $kind restart(s); $seen seen, $killed killed"
done
expect_eq "metrics against the undisturbed run" "$(sql "$DB" "$METRICS" | tr '|' ' ')" "$EXPECTED"
LOSSES=$(sql "$DB" "SELECT SUM(infra_losses) FROM jobs")
echo "ok: $sent kills ($WORKER_KILLS workers, $COORDINATOR_KILLS coordinator), $TOTAL jobs \
succeeded once each, $LOSSES infrastructure loss(es) absorbed, metrics unchanged"
