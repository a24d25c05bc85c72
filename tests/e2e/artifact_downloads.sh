#!/usr/bin/env bash
# Every artifact of a campaign downloaded over the campaign page's API (`rlpos-campaign serve`)
# is the file `rlpos-campaign artifacts ID --out DIR` exports: the same bytes, the sha256 the
# API lists. A small campaign trains two policies (their policy, curve, trajectory and result
# files are the artifacts), then serve reads its database on a free loopback port.
# Usage: artifact_downloads.sh BIN_DIR SOURCE_DIR
source "$(dirname "$0")/lib.sh"
PYTHON=/usr/bin/python3  # the standard library only
DB=$WORK/rlpos.db
run_campaign "$SRC/tests/e2e/campaigns/artifacts.json" --no-progress
ARTIFACTS=$(sql "$DB" "SELECT COUNT(*) FROM artifacts")
[ "$ARTIFACTS" -ge 6 ] || fail "expected the artifacts of two train jobs, the database has $ARTIFACTS"

"$CAMPAIGN" artifacts "$ID" --db "$DB" --out "$WORK/exported" 2>"$WORK/export.err" \
  || fail "artifacts --out failed: $(cat "$WORK/export.err")"

# A free loopback port: the server picks one and says which.
"$CAMPAIGN" serve --db "$DB" --listen 127.0.0.1:0 >"$WORK/serve.txt" 2>"$WORK/serve.err" &
SERVE=$!
BG_PIDS+=("$SERVE")
wait_until 20 grep -q '^serving ' "$WORK/serve.txt" || fail "serve did not start: $(cat "$WORK/serve.err")"
URL=$(sed -n 's/^serving .* on \(http[^ ]*\).*/\1/p' "$WORK/serve.txt")

"$PYTHON" "$SRC/tests/e2e/artifact_downloads.py" --url "$URL" --campaign "$ID" \
  --exported "$WORK/exported" --count "$ARTIFACTS" || fail "the downloads differ from the export"
kill -0 "$SERVE" || fail "serve died"
echo "ok: the $ARTIFACTS artifacts of campaign $ID download whole, as artifacts --out has them"
