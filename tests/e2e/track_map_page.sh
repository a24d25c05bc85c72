#!/usr/bin/env bash
# The campaign page plays a track run on its map, in a real browser (headless Chromium driven by
# Selenium): a small analytic track campaign on the street of campaigns/mobility.json (its
# pedestrians walk) runs to the end, `rlpos-campaign serve` reads its database, and
# track_map_page.py moves the map's time slider and checks that the time label, a UAV and a UE
# move, then saves screenshots into this test's output folder.
# Skips (77) where Chromium, its driver or Selenium is missing.
# Usage: track_map_page.sh BIN_DIR SOURCE_DIR OUTPUT_DIR
source "$(dirname "$0")/lib.sh"
start_browser_test "${3:-}"
cat >"$WORK/walk.json" <<JSON
{
  "name": "track-map",
  "scenarios": [{"file": "$SRC/campaigns/scenarios/mobility-street.json",
                 "set": ["env.decision_interval=1"]}],
  "rng_runs": [1, 1],
  "positioners": [],
  "track": {"positioners": ["centroid", "centroid-track", "oracle-track"], "duration": 40},
  "job_timeout_s": 120
}
JSON
"$CAMPAIGN" run "$WORK/walk.json" --workers 2 --db "$DB" --tag "$TAG" --no-progress \
  >"$WORK/out.txt" 2>"$WORK/err.txt" || { cat "$WORK/err.txt" >&2; fail "the campaign failed"; }
expect_eq "track runs stored" "$(sql "$DB" "SELECT COUNT(*) FROM track_runs")" 3
ID=$(sql "$DB" "SELECT id FROM campaigns")

# A free loopback port: the server picks one and says which.
"$CAMPAIGN" serve --db "$DB" --listen 127.0.0.1:0 >"$WORK/serve.txt" 2>"$WORK/serve.err" &
SERVE=$!
BG_PIDS+=("$SERVE")
wait_until 20 grep -q '^serving ' "$WORK/serve.txt" || fail "serve did not start: $(cat "$WORK/serve.err")"
URL=$(sed -n 's/^serving .* on \(http[^ ]*\).*/\1/p' "$WORK/serve.txt")

"$PYTHON" "$SRC/tests/e2e/track_map_page.py" --url "$URL" --campaign "$ID" --scenario street \
  --positioners centroid,centroid-track,oracle-track --frames 40 --out "$OUT" --deadline 60 \
  || fail "the page check failed"
kill -0 "$SERVE" || fail "serve died"
echo "screenshots in $OUT"
