#!/usr/bin/env bash
# rlpos-sim track as a user runs it: UEs that walk (a generated random_waypoint scenario) and
# UAVs that follow within their speed limits. A static scenario scores every interval as
# `position` scores the placement; the same RngRun gives the same bytes; the tracking oracle
# beats the oracle held at its t = 0 placement; at packet level the warm-up's intervals are not
# scored; bad input is a one-line error.
source "$(dirname "$0")/lib.sh" "$1" "$2"
SIM=$BIN/rlpos-sim
B=$SRC/campaigns/scenarios/b.json
json() {  # json FILE EXPRESSION: a value of the JSON in FILE (python, as `d`)
  python3 -c "import json,sys; d=json.load(open(sys.argv[1])); print($2)" "$1"
}

# Static UEs: every interval is the placement's analytic reward, as `position` gives it.
for p in baseline centroid; do
  "$SIM" position --scenario "$B" --positioner "$p" --json >"$WORK/$p.position.json" \
    || fail "position $p"
  "$SIM" track --scenario "$B" --positioner "$p" --duration 3 --RngRun 1 --json \
    --set env.decision_interval=0.5 >"$WORK/$p.track.json" || fail "track $p"
  expect_eq "$p: intervals" "$(json "$WORK/$p.track.json" "len(d['series'])")" "6"
  expect_eq "$p: rewards that differ from position's" "$(python3 -c "
import json, sys
position = json.load(open(sys.argv[1]))['reward']
track = json.load(open(sys.argv[2]))
print(sum(1 for i in track['series'] if i['reward'] != position) + (track['mean_reward'] != position))
" "$WORK/$p.position.json" "$WORK/$p.track.json")" "0"
done

# UEs that walk: a generated campus, every UE on a random waypoint walk. A coarse grid and a
# decision every second keep the oracle quick.
"$SIM" generate --seed 4 --style campus --mobility random_waypoint --out "$WORK/walk.json" \
  || fail "generate"
run() {  # run POSITIONER RNGRUN [ARGS...]: track's JSON on stdout
  local p=$1 r=$2
  shift 2
  "$SIM" track --scenario "$WORK/walk.json" --positioner "$p" --duration 60 --RngRun "$r" \
    --set env.step=10 --set env.decision_interval=1 "$@" --json
}
run oracle-track 1 >"$WORK/track1.json" || fail "oracle-track"
run oracle-track 1 >"$WORK/track1-again.json" || fail "oracle-track again"
cmp -s "$WORK/track1.json" "$WORK/track1-again.json" || fail "the same RngRun gave other numbers"
run oracle-track 2 >"$WORK/track2.json" || fail "oracle-track, RngRun 2"
[ "$(python3 -c "
import json, sys
print(json.load(open(sys.argv[1]))['series'] == json.load(open(sys.argv[2]))['series'])
" "$WORK/track1.json" "$WORK/track2.json")" = False ] || fail "RngRun 2 gave RngRun 1's series"
run oracle 1 >"$WORK/held1.json" || fail "oracle"
tracking=$(json "$WORK/track1.json" "d['mean_reward']")
held=$(json "$WORK/held1.json" "d['mean_reward']")
python3 -c "import sys; sys.exit(0 if float(sys.argv[1]) >= float(sys.argv[2]) else 1)" \
  "$tracking" "$held" || fail "oracle-track's mean reward $tracking is below the held oracle's $held"
expect_eq "held oracle: distance flown" "$(json "$WORK/held1.json" "d['distance_flown_m']")" "0.0"

# The speed limit holds, interval by interval, and binds: the oracle's targets jump.
run oracle-track 1 --set uav.max_speed=2 --set uav.max_climb=0.5 >"$WORK/slow.json" \
  || fail "oracle-track, slow"
expect_eq "legs beyond 2 m across or 0.5 m up; the longest across" "$(python3 -c "
import json, math, sys
d = json.load(open(sys.argv[1]))
bad, longest = 0, 0.0
for a, b in zip(d['series'], d['series'][1:]):
    (x0, y0, z0), (x1, y1, z1) = a['positions'][0], b['positions'][0]
    bad += math.hypot(x1 - x0, y1 - y0) > 2 + 1e-9 or abs(z1 - z0) > 0.5 + 1e-9
    longest = max(longest, math.hypot(x1 - x0, y1 - y0))
print(bad, round(longest, 6))
" "$WORK/slow.json")" "0 2.0"

# Packet level: one ns-3 run in which the UAV flies; the intervals that start within the
# warm-up (1 s) are flown, listed and not scored; the packets give each interval its delay.
"$SIM" track --scenario "$B" --positioner centroid-track --duration 2 --RngRun 1 --json \
  --fidelity packet --set env.decision_interval=0.5 >"$WORK/packet.json" || fail "track packet"
expect_eq "packet: intervals, scored, scored flags, delays" "$(json "$WORK/packet.json" \
  "len(d['series']), d['scored_intervals'], [i['scored'] for i in d['series']],
   sum(1 for i in d['series'] if i['mean_delay_ms'] > 0)")" "4 2 [False, False, True, True] 4"
expect_eq "packet: the mean reward of the scored intervals" "$(json "$WORK/packet.json" \
  "abs(d['mean_reward'] - sum(i['reward'] for i in d['series'][2:]) / 2) < 1e-12")" "True"

# Bad input: one line on stderr, exit code 2, nothing on stdout.
expect_error() {  # expect_error FRAGMENT ARGS...
  local fragment=$1 rc=0
  shift
  "$SIM" track "$@" >"$WORK/out.txt" 2>"$WORK/err.txt" || rc=$?
  expect_eq "exit code of track $*" "$rc" "2"
  [ ! -s "$WORK/out.txt" ] || fail "track $* printed on stdout: $(cat "$WORK/out.txt")"
  expect_eq "stderr lines of track $*" "$(wc -l <"$WORK/err.txt")" "1"
  grep -q "^rlpos-sim: error: .*$fragment" "$WORK/err.txt" \
    || fail "track $*: expected '$fragment', got: $(cat "$WORK/err.txt")"
}
expect_error "teleport" --scenario "$B" --positioner teleport --duration 10 --RngRun 1
expect_error "--policy: is required for the rl positioner in track" --scenario "$B" --positioner rl --duration 10 --RngRun 1
expect_error "--policy: only the rl positioner flies a policy" --scenario "$B" --positioner oracle \
  --policy "$SRC/policies/generalist-1uav" --duration 10 --RngRun 1
expect_error "--duration: must be at least env.decision_interval" \
  --scenario "$B" --positioner oracle --duration -5 --RngRun 1
expect_error "--duration: leaves no interval after simulation.warmup (1 s) at packet level" \
  --scenario "$B" --positioner oracle --duration 1 --RngRun 1 --fidelity packet
expect_error "--set uav.max_speed=-1: /uav/max_speed" \
  --scenario "$B" --positioner oracle --duration 10 --RngRun 1 --set uav.max_speed=-1
expect_error "/uav/max_climb" \
  --scenario "$B" --positioner oracle --duration 10 --RngRun 1 --set uav.max_climb=1000
echo "ok: track scores static runs as position does, repeats itself, follows walking UEs within the speed limits, runs at packet level, and refuses bad input"
