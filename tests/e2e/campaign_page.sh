#!/usr/bin/env bash
# The campaign page in a real browser (headless Chromium driven by Selenium): a small campaign
# runs in the background, `rlpos-campaign serve` reads its database, and campaign_page.py checks
# that the campaign and its plots render with one series per positioner, that the progress
# advances on the page without a reload, and saves a screenshot into this test's output folder.
# Skips (77) where Chromium, its driver or Selenium is missing.
# Usage: campaign_page.sh BIN_DIR SOURCE_DIR OUTPUT_DIR
source "$(dirname "$0")/lib.sh"
start_browser_test "${3:-}"
CAMPAIGN_FILE=$SRC/tests/e2e/campaigns/page_live.json
ID=$("$CAMPAIGN" run "$CAMPAIGN_FILE" --dry-run | sed -n 's/^campaign \([0-9a-f]*\) .*/\1/p')
[ -n "$ID" ] || fail "no campaign id from --dry-run"
start_run "$CAMPAIGN_FILE"
campaign_stored() { [ "$(sql "$DB" "SELECT COUNT(*) FROM campaigns WHERE id = '$ID'" 2>/dev/null)" = 1 ]; }
wait_until 60 campaign_stored || fail "the campaign never reached the database"

# A free loopback port: the server picks one and says which.
"$CAMPAIGN" serve --db "$DB" --listen 127.0.0.1:0 >"$WORK/serve.txt" 2>"$WORK/serve.err" &
SERVE=$!
BG_PIDS+=("$SERVE")
wait_until 20 grep -q '^serving ' "$WORK/serve.txt" || fail "serve did not start: $(cat "$WORK/serve.err")"
URL=$(sed -n 's/^serving .* on \(http[^ ]*\).*/\1/p' "$WORK/serve.txt")

"$PYTHON" "$SRC/tests/e2e/campaign_page.py" --url "$URL" --campaign "$ID" --positioners 3 \
  --scenarios 2 --out "$OUT" --deadline 600 || fail "the page check failed"
kill -0 "$SERVE" || fail "serve died"
wait "$RUN" || fail "run exited $?"
echo "screenshots in $OUT"
