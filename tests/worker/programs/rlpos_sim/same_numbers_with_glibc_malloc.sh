#!/usr/bin/env bash
# rlpos-sim links tcmalloc (rlpos_use_tcmalloc); the numbers must not depend on the allocator. Every
# shipped scenario is evaluated at its baseline by rlpos-sim and by its glibc-malloc twin
# (scripts/lib/glibc_malloc_twin), and a packet-level track run too: the same JSON, byte for byte.
# Usage: same_numbers_with_glibc_malloc.sh BIN_DIR SOURCE_DIR
set -euo pipefail
bin=$1 src=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

"$src/scripts/lib/glibc_malloc_twin" "$bin" "$work/twin"
twin=$work/twin/bin/rlpos-sim
loads() { [[ "$(ldd "$1")" == *libtcmalloc* ]]; }  # the whole list first: no SIGPIPE
loads "$bin/rlpos-sim" || fail "rlpos-sim does not load tcmalloc"
ldd "$twin" >/dev/null || fail "ldd cannot read the twin"
! loads "$twin" || fail "the twin still loads tcmalloc"

# same ARGS...: both programs print the same bytes, and something.
same() {
  "$bin/rlpos-sim" "$@" >"$work/tcmalloc.out" || fail "rlpos-sim $* exited $?"
  "$twin" "$@" >"$work/glibc.out" || fail "the twin, $* exited $?"
  [ -s "$work/tcmalloc.out" ] || fail "rlpos-sim $* printed nothing"
  cmp -s "$work/tcmalloc.out" "$work/glibc.out" ||
    fail "rlpos-sim $*: tcmalloc and glibc's malloc differ: $(diff "$work/tcmalloc.out" "$work/glibc.out" | head -5)"
}

count=0
for scenario in "$src"/campaigns/scenarios/*.json; do
  positions=$("$src/scripts/lib/baseline_flags" "$bin/rlpos-sim" "$scenario")
  # Short runs (0.3 s of traffic after a 0.3 s warm-up): every packet path runs, at a third of
  # the cost of the scenarios' own timing.
  # shellcheck disable=SC2086 # one word per flag and position
  same eval --scenario "$scenario" $positions --duration 0.6 --set simulation.warmup=0.3 \
    --RngRun 1 --json
  count=$((count + 1))
done
[ "$count" -ge 8 ] || fail "only $count shipped scenarios found"
same track --scenario "$src/campaigns/scenarios/mobility-street.json" --positioner centroid-track \
  --duration 4 --RngRun 1 --set env.decision_interval=1 --fidelity packet --json
echo "tcmalloc and glibc's malloc: the same numbers on $count scenarios and a track run"
