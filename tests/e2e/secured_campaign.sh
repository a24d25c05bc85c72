#!/usr/bin/env bash
# DDS Security across a real link. Two network namespaces joined by a veth pair that this test
# creates (private 10.x addresses) and removes: a secured coordinator in one, two secured workers
# in the other (the identities "worker" and "host-b"), a secured client submitting. Beside them,
# unsecured participants: a hostile peer on the same domain and link, and an --insecure client.
# Expected: the campaign completes with the metrics of an undisturbed run; the unsecured peer
# hears nothing of it (while it hears another unsecured peer across the link: the link does
# carry unsecured traffic) and changes nothing; the insecure client gets no answer; a raw
# capture of the link finds no job id, campaign name or scenario text (while it does find a
# clear-text marker sent over the same link: the capture works). Needs root; skips (77)
# otherwise.
source "$(dirname "$0")/lib.sh"
source "$(dirname "$0")/netns.sh"

NS_C=rlpos-c-$$
NS_W=rlpos-w-$$
IF_C=rlc$$
IF_W=rlw$$
NET=10.$((200 + $$ % 50)).$(($$ / 50 % 250))
A_C=$NET.1
A_W=$NET.2
add_namespace "$NS_C"
add_namespace "$NS_W"
ip link add "$IF_C" netns "$NS_C" type veth peer name "$IF_W" netns "$NS_W" \
  || { echo "skip: cannot create a veth pair"; exit 77; }
ip -n "$NS_C" addr add "$A_C/24" dev "$IF_C"
ip -n "$NS_W" addr add "$A_W/24" dev "$IF_W"
ip -n "$NS_C" link set "$IF_C" up
ip -n "$NS_W" link set "$IF_W" up
# Prefixes, not functions: a backgrounded function would be a subshell, and $! its pid.
IN_C=(ip netns exec "$NS_C")
IN_W=(ip netns exec "$NS_W")
DOMAIN=$((1 + $$ % 200))
XML_C=$(dds_xml "$IF_C" "$A_W")
XML_W=$(dds_xml "$IF_W" "$A_C")
CAMPAIGN_FILE=$SRC/tests/e2e/campaigns/tiny_b.json

# The undisturbed run, for the metrics to compare with (loopback, unsecured, no namespaces).
"$CAMPAIGN" run "$CAMPAIGN_FILE" --workers 1 --db "$WORK/calm/calm.db" --tag "$TAG-calm" \
  --no-progress >/dev/null 2>"$WORK/calm.err" || fail "undisturbed run: $(tail -3 "$WORK/calm.err")"

SEC=$WORK/sec
"$CAMPAIGN" security init "$SEC" >/dev/null
"$CAMPAIGN" security add-worker "$SEC" host-b >/dev/null

mkdir -p "$WORK/logs/daemons"
"${IN_C[@]}" python3 "$SRC/tests/e2e/capture_link.py" "$IF_C" "$WORK/link.pcap" 600 >"$WORK/capture.out" &
CAPTURE=$!
BG_PIDS+=("$CAPTURE")
wait_until 10 grep -q capturing "$WORK/capture.out" || fail "the capture did not start"

DB=$WORK/rlpos.db
"${IN_C[@]}" "$BIN/rlpos-coordinator" --db "$DB" --domain "$DOMAIN" --dds-config "$XML_C" \
  --security "$SEC" 2>"$WORK/logs/daemons/coordinator.log" &
COORDINATOR=$!
BG_PIDS+=("$COORDINATOR")
WORKER_PIDS=()
for identity in worker host-b; do
  "${IN_W[@]}" "$BIN/rlpos-worker" --slots 1 --id "$identity" --work-dir "$WORK/work-$identity" \
    --domain "$DOMAIN" --dds-config "$XML_W" --security "$SEC" --identity "$identity" \
    2>"$WORK/logs/daemons/$identity.log" &
  WORKER_PIDS+=("$!")
  BG_PIDS+=("$!")
done

ID=$("${IN_C[@]}" "$CAMPAIGN" submit "$CAMPAIGN_FILE" --domain "$DOMAIN" --dds-config "$XML_C" \
  --security "$SEC" 2>"$WORK/submit.err") || fail "secured submit: $(cat "$WORK/submit.err")"
wait_until 60 bash -c "[ \"\$(sqlite3 '$DB' \"SELECT COUNT(*) FROM jobs
  WHERE state IN ('running', 'succeeded')\")\" -ge 1 ]" || fail "nothing started"

# The unsecured side: a hostile peer on the same domain and link, and an --insecure client. The
# peer must hear nothing of the campaign; in the same window it must hear another unsecured
# peer across the link (the positive control: unsecured traffic does cross it here). That one
# only writes (no reader: nothing of the campaign goes to it over the captured link), and knows
# nothing of the campaign (no database, an empty scenario).
"${IN_C[@]}" "$BIN/rlpos-hostile-peer" "$DOMAIN" "$XML_C" "$DB" worker "$SRC/campaigns/scenarios/b.json" 6 \
  >"$WORK/peer.out" 2>&1 &
PEER=$!
BG_PIDS+=("$PEER")
"${IN_W[@]}" "$BIN/rlpos-hostile-peer" "$DOMAIN" "$XML_W" "$WORK/none.db" host-b /dev/null 6 \
  --write-only >"$WORK/speaker.out" 2>&1 &
SPEAKER=$!
BG_PIDS+=("$SPEAKER")
"$CAMPAIGN" status "$ID" --db "$DB" --watch --period 0.5 >/dev/null || fail "status --watch"
wait "$PEER" || fail "the hostile peer failed: $(cat "$WORK/peer.out")"
wait "$SPEAKER" || fail "the writing peer failed: $(cat "$WORK/speaker.out")"
SUMMARY=$(tail -n 1 "$WORK/peer.out")
grep -q "^sent [1-9]" <<<"$SUMMARY" || fail "the hostile peer sent nothing: $SUMMARY"
grep -q "; heard 0 (" <<<"$SUMMARY" || fail "an unsecured peer heard the campaign: $SUMMARY"
grep -Eq "; heard from peers [1-9]" <<<"$SUMMARY" \
  || fail "the unsecured peer heard nothing of the other one across the link: $SUMMARY"
# Once the peer is gone (it would answer an unsecured request itself: that is what --insecure
# risks), an --insecure client asks the secured coordinator to cancel: nobody answers.
set +e
"${IN_W[@]}" "$CAMPAIGN" cancel "$ID" --domain "$DOMAIN" --dds-config "$XML_W" --insecure --timeout 3 \
  2>"$WORK/insecure.err"
CODE=$?
set -e
expect_eq "exit code of an --insecure client's cancel" "$CODE" 4
grep -q "no coordinator answered" "$WORK/insecure.err" || fail "insecure client: $(cat "$WORK/insecure.err")"

expect_eq "campaign state" "$(sql "$DB" "SELECT state FROM campaigns WHERE id = '$ID'")" finished

# A clear-text marker over the same link, so that the capture is shown to see payloads.
MARKER=rlpos-capture-marker-$$
"${IN_W[@]}" python3 -c "import socket,sys; s=socket.socket(socket.AF_INET, socket.SOCK_DGRAM); \
s.sendto(sys.argv[1].encode(), (sys.argv[2], 9))" "$MARKER" "$A_C"
wait_until 10 grep -qaF "$MARKER" "$WORK/link.pcap" || fail "the capture does not see the link"
kill "$CAPTURE"
wait "$CAPTURE" || true

for pid in "$COORDINATOR" "${WORKER_PIDS[@]}"; do
  kill -0 "$pid" 2>/dev/null || fail "a daemon died (pid $pid)"
done
expect_complete "$DB" 6
expect_eq "workers that ran jobs" \
  "$(sql "$DB" "SELECT COUNT(DISTINCT worker_id) FROM jobs WHERE worker_id IN ('worker', 'host-b')")" 2
expect_eq "attempts" "$(sql "$DB" "SELECT MAX(attempt) FROM jobs")" 1
METRICS="SELECT scenario, positioner, rng_run, throughput_mbps, delay_ms, n_los, x, y, z
  FROM v_eval_runs ORDER BY 1, 2, 3"
expect_eq "metrics against the undisturbed run" "$(sql "$DB" "$METRICS")" \
  "$(sql "$WORK/calm/calm.db" "$METRICS")"

# Nothing of the campaign in clear text on the link. (The handshake does show each participant's
# certificate and signed permissions, hence the topic names: DDS Security's design, not a leak.)
FRAMES=$(sed -n 's/^captured \([0-9]*\) frames$/\1/p' "$WORK/capture.out")
[ "${FRAMES:-0}" -ge 100 ] || fail "only ${FRAMES:-0} frames captured"
JOB=$(sql "$DB" "SELECT id FROM jobs WHERE kind = 'eval' LIMIT 1")
for needle in "$ID" "$JOB" "tiny-b" "baseline/run" "Obstacle-rich, homogeneous" "north-block"; do
  if grep -qaF -- "$needle" "$WORK/link.pcap"; then fail "clear text on the link: '$needle'"; fi
done
echo "ok: secured campaign across namespaces ($FRAMES frames, no clear text; $SUMMARY)"
