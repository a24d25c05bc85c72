#!/usr/bin/env bash
# Many hosts, for real: a secured coordinator in one network namespace and two secured workers
# in two others (identities "worker" and "host-b"), joined through a bridge in the coordinator's
# namespace by veth pairs this test creates and removes (private 10.x addresses). Mid-campaign
# the coordinator's link goes down until both workers are declared lost (2 s lease), then comes
# back: the workers return, their stale attempts are stopped, the jobs run again. Later the
# second worker's host disappears mid-job (its processes killed, its namespace deleted).
# Expected: the campaign completes, every job succeeded exactly once, no job used a retry
# (retries is 0), and the metrics equal the recorded ones of an undisturbed run. Root only.
source "$(dirname "$0")/lib.sh"
source "$(dirname "$0")/netns.sh"

NS_C=rlpos-lc-$$
NS_1=rlpos-l1-$$
NS_2=rlpos-l2-$$
NET=10.$((150 + $$ % 50)).$(($$ / 50 % 250))
A_C=$NET.1
A_1=$NET.2
A_2=$NET.3
add_namespace "$NS_C"
add_namespace "$NS_1"
add_namespace "$NS_2"
ip -n "$NS_C" link add name rlbr type bridge mcast_snooping 0 \
  || { echo "skip: cannot create a bridge"; exit 77; }
ip link add vc1 netns "$NS_C" type veth peer name vw1 netns "$NS_1" \
  || { echo "skip: cannot create a veth pair"; exit 77; }
ip link add vc2 netns "$NS_C" type veth peer name vw2 netns "$NS_2"
for port in vc1 vc2; do
  ip -n "$NS_C" link set "$port" master rlbr
  ip -n "$NS_C" link set "$port" up
done
ip -n "$NS_C" addr add "$A_C/24" dev rlbr
ip -n "$NS_1" addr add "$A_1/24" dev vw1
ip -n "$NS_2" addr add "$A_2/24" dev vw2
ip -n "$NS_C" link set rlbr up
ip -n "$NS_1" link set vw1 up
ip -n "$NS_2" link set vw2 up
IN_C=(ip netns exec "$NS_C")
DOMAIN=$((1 + $$ % 200))
SEC=$WORK/sec
"$CAMPAIGN" security init "$SEC" >/dev/null
"$CAMPAIGN" security add-worker "$SEC" host-b >/dev/null
DDS_C=(--domain "$DOMAIN" --dds-config "$(dds_xml rlbr "$A_1" "$A_2")" --security "$SEC")

mkdir -p "$WORK/logs/daemons"
DB=$WORK/rlpos.db
"${IN_C[@]}" "$BIN/rlpos-coordinator" --db "$DB" "${DDS_C[@]}" \
  2>"$WORK/logs/daemons/coordinator.log" &
COORDINATOR=$!
BG_PIDS+=("$COORDINATOR")
ip netns exec "$NS_1" "$BIN/rlpos-worker" --slots 1 --id worker --work-dir "$WORK/work-1" \
  --domain "$DOMAIN" --dds-config "$(dds_xml vw1 "$A_C")" --security "$SEC" \
  2>"$WORK/logs/daemons/worker.log" &
BG_PIDS+=("$!")
ip netns exec "$NS_2" "$BIN/rlpos-worker" --slots 1 --id host-b --work-dir "$WORK/work-2" \
  --domain "$DOMAIN" --dds-config "$(dds_xml vw2 "$A_C")" --security "$SEC" --identity host-b \
  2>"$WORK/logs/daemons/host-b.log" &
BG_PIDS+=("$!")

ID=$("${IN_C[@]}" "$CAMPAIGN" submit "$SRC/tests/e2e/campaigns/chaos_fixed.json" "${DDS_C[@]}" \
  2>"$WORK/submit.err") || fail "submit: $(cat "$WORK/submit.err")"
count() { sql "$DB" "$1" 2>/dev/null || echo 0; }
succeeded() { count "SELECT COUNT(*) FROM jobs WHERE state = 'succeeded'"; }
wait_until 120 bash -c "[ \"\$(sqlite3 '$DB' \"SELECT COUNT(*) FROM jobs
  WHERE state = 'succeeded'\")\" -ge 2 ]" || fail "the campaign did not start"

# 1. The coordinator's link goes down until both workers are lost, then comes back.
ip -n "$NS_C" link set rlbr down
both_lost() { [ "$(count "SELECT COUNT(*) FROM workers WHERE state = 'lost'")" -eq 2 ]; }
wait_until 60 both_lost || fail "the workers were not declared lost while the link was down"
BEFORE=$(succeeded)
ip -n "$NS_C" link set rlbr up
both_back() { [ "$(count "SELECT COUNT(*) FROM workers WHERE state = 'alive'")" -eq 2 ]; }
wait_until 60 both_back || fail "the workers did not come back with the link"
moved_on() { [ "$(succeeded)" -gt "$BEFORE" ]; }
wait_until 120 moved_on || fail "no job succeeded after the link came back"

# 2. host-b's host disappears in the middle of a job.
on_b() { [ "$(count "SELECT COUNT(*) FROM jobs WHERE state = 'running' AND worker_id = 'host-b'")" -ge 1 ]; }
wait_until 120 on_b || fail "no job ran on host-b after the link came back"
ip netns pids "$NS_2" | xargs -r kill -9
ip netns del "$NS_2"

"$CAMPAIGN" status "$ID" --db "$DB" --watch --period 0.5 >/dev/null || fail "status --watch"
kill -0 "$COORDINATOR" 2>/dev/null || fail "the coordinator died"
expect_complete "$DB" 18
expect_eq "jobs that used a retry" "$(sql "$DB" "SELECT COUNT(*) FROM jobs
  WHERE attempt - infra_losses > 1")" 0
LOSSES=$(sql "$DB" "SELECT SUM(infra_losses) FROM jobs")
[ "$LOSSES" -ge 2 ] || fail "only $LOSSES infrastructure loss(es): the faults did not hit running jobs"
expect_eq "host-b's state" "$(sql "$DB" "SELECT state FROM workers WHERE id = 'host-b'")" lost
expect_eq "metrics against the undisturbed run" "$(sql "$DB" "SELECT scenario, positioner,
  rng_run, printf('%.6f', throughput_mbps), printf('%.6f', delay_ms), n_los, x, y, z
  FROM v_eval_runs ORDER BY 1, 2, 3" | tr '|' ' ')" \
  "$(grep -E ' (baseline|centroid|oracle) ' "$SRC/tests/e2e/golden/mini_fixed_positions.txt")"
echo "ok: link loss and a vanished host absorbed ($LOSSES infrastructure losses), 18 jobs once each"
