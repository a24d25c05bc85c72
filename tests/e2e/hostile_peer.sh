#!/usr/bin/env bash
# A hostile participant on the campaign's DDS domain (rlpos-hostile-peer) attacks a running
# campaign: bad assignments to the worker, forged events, a forged dispose of the worker's
# status, forged replies, invalid submits. Nothing runs, nothing is recorded, both daemons stay
# up, and the campaign completes with the metrics of an undisturbed run.
source "$(dirname "$0")/lib.sh"
PEER=$BIN/rlpos-hostile-peer
CANARY=/tmp/rlpos-hostile-canary
rm -f "$CANARY"
CAMPAIGN_FILE=$SRC/tests/e2e/campaigns/tiny_b.json

# The undisturbed run, for the metrics to compare with.
"$CAMPAIGN" run "$CAMPAIGN_FILE" --workers 1 --db "$WORK/calm/calm.db" --tag "$TAG-calm" \
  --no-progress >/dev/null 2>"$WORK/calm.err" || fail "undisturbed run: $(tail -3 "$WORK/calm.err")"

DB=$WORK/rlpos.db
DOMAIN=$((1 + $$ % 200))
DDS=(--loopback "$TAG" --domain "$DOMAIN")
WORKER=$TAG-w
mkdir -p "$WORK/logs/daemons"
"$BIN/rlpos-coordinator" --db "$DB" "${DDS[@]}" 2>"$WORK/logs/daemons/coordinator.log" &
COORDINATOR=$!
BG_PIDS+=("$COORDINATOR")
"$BIN/rlpos-worker" --slots 1 --id "$WORKER" --work-dir "$WORK/work" "${DDS[@]}" \
  2>"$WORK/logs/daemons/worker.log" &
WORKER_PID=$!
BG_PIDS+=("$WORKER_PID")

ID=$("$CAMPAIGN" submit "$CAMPAIGN_FILE" "${DDS[@]}" 2>"$WORK/submit.err") \
  || fail "submit: $(cat "$WORK/submit.err")"
# Attack once the worker follows the coordinator, i.e. once a job runs.
wait_until 60 bash -c "[ \"\$(sqlite3 '$DB' \"SELECT COUNT(*) FROM jobs
  WHERE state IN ('running', 'succeeded')\")\" -ge 1 ]" || fail "nothing started"
"$PEER" "$DOMAIN" "$TAG" "$DB" "$WORKER" "$SRC/campaigns/scenarios/b.json" 12 \
  >"$WORK/peer.out" 2>&1 &
PEER_PID=$!
BG_PIDS+=("$PEER_PID")
wait_until 30 grep -q "^matched the daemons" "$WORK/peer.out" \
  || fail "the hostile peer did not match the daemons: $(cat "$WORK/peer.out")"
# A client's submit during the attack still gets the coordinator's answer, not the peer's
# forged one. A client answered before the peer matched its request writer has gone before the
# forgery: submit again, a few times at most, until the peer forged a reply to a live client.
forged() { grep -q "^forged a reply to " "$WORK/peer.out"; }
for attempt in 1 2 3 4 5; do
  AGAIN=$("$CAMPAIGN" submit "$CAMPAIGN_FILE" "${DDS[@]}" 2>"$WORK/again.err") \
    || fail "submit $attempt during the attack: $(cat "$WORK/again.err")"
  expect_eq "campaign id of submit $attempt during the attack" "$AGAIN" "$ID"
  if forged; then break; fi
done
FORGED_ON=$attempt
"$CAMPAIGN" status "$ID" --db "$DB" --watch --period 0.5 >/dev/null || fail "status --watch"
wait "$PEER_PID" || fail "the hostile peer failed: $(cat "$WORK/peer.out")"
SUMMARY=$(tail -n 1 "$WORK/peer.out")
forged || fail "the hostile peer forged no reply to a client (5 submits): $SUMMARY"
grep -q "^sent [1-9]" <<<"$SUMMARY" || fail "the hostile peer sent nothing: $SUMMARY"
# Unsecured DDS hides nothing: the peer heard the assignments and the worker's status (the
# positive control of secured_campaign.sh, where it must hear nothing).
grep -Eq "rlpos_job_assignment [1-9].*rlpos_worker_status [1-9]" <<<"$SUMMARY" \
  || fail "the hostile peer heard nothing of an unsecured campaign: $SUMMARY"

kill -0 "$COORDINATOR" 2>/dev/null || fail "the coordinator died"
kill -0 "$WORKER_PID" 2>/dev/null || fail "the worker died"
expect_complete "$DB" 6
expect_eq "campaigns" "$(sql "$DB" "SELECT COUNT(*) FROM campaigns")" 1
expect_eq "jobs run elsewhere than on the worker" \
  "$(sql "$DB" "SELECT COUNT(*) FROM jobs WHERE worker_id != '$WORKER'")" 0
expect_eq "attempts" "$(sql "$DB" "SELECT MAX(attempt) FROM jobs")" 1
expect_eq "worker state" "$(sql "$DB" "SELECT state FROM workers WHERE id = '$WORKER'")" alive
[ ! -e "$CANARY" ] || fail "a hostile override ran"
# Only the campaign's own job folders exist on the worker.
expect_eq "foreign folders in the worker's work dir" \
  "$(find "$WORK/work" -mindepth 1 -maxdepth 1 ! -name "$ID" | wc -l)" 0
# The drops were noticed (and said), and the metrics are those of the undisturbed run.
grep -q "dropped job event sample" "$WORK/logs/daemons/coordinator.log" \
  || fail "the coordinator did not report the forged events"
grep -q "dropped job assignment sample" "$WORK/logs/daemons/worker.log" \
  || fail "the worker did not report the foreign assignments"
METRICS="SELECT scenario, positioner, rng_run, throughput_mbps, delay_ms, n_los, x, y, z
  FROM v_eval_runs ORDER BY 1, 2, 3"
expect_eq "metrics against the undisturbed run" "$(sql "$DB" "$METRICS")" \
  "$(sql "$WORK/calm/calm.db" "$METRICS")"
echo "ok: a hostile peer changed nothing (a reply forged on submit $FORGED_ON; $SUMMARY)"
