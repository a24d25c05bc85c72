#!/usr/bin/env bash
# The campaign page on a large database: a campaign of N jobs (scenarios B and C, baseline,
# centroid and oracle; default 10002) expanded into a fresh store with made-up results
# (rlpos-bench-fill-store), `rlpos-campaign serve` over it on a free loopback port, then:
#   api ms      median wall time of each API endpoint (curl, 5 requests each)
#   page ms     headless Chromium: navigation start to the campaign view drawn whole (summary,
#               distributions, maps: the page's "rlpos-plotted" mark), median of 3 fresh loads
#   serve RSS   the server's resident memory before and after the loads, and its peak
# Usage: scripts/bench_campaign_page.sh [N_JOBS] [BUILD_DIR]
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
jobs=${1:-10002}
bin=${2:-$here/build}/bin
for tool in curl chromium chromedriver; do
  command -v "$tool" >/dev/null || { echo "needs $tool" >&2; exit 2; }
done
for program in rlpos-bench-fill-store rlpos-campaign; do
  [ -x "$bin/$program" ] || { echo "$bin/$program: missing (build first)" >&2; exit 2; }
done
work=$(mktemp -d "${TMPDIR:-/tmp}/rlpos-bench-page.XXXXXX")
serve_pid=
cleanup() {
  [ -n "$serve_pid" ] && kill "$serve_pid" 2>/dev/null || true
  wait 2>/dev/null || true
  rm -rf "$work"
}
trap cleanup EXIT

# 2 scenarios x (3 position jobs + 3 evals per run).
runs=$(((jobs / 2 - 3) / 3))
cat >"$work/campaign.json" <<JSON
{"name": "bench-page", "scenarios": ["$here/campaigns/scenarios/b.json", "$here/campaigns/scenarios/c.json"],
 "rng_runs": [1, $runs], "positioners": ["baseline", "centroid", "oracle"],
 "eval": {"duration": 2, "warmup": 0.5}, "retries": 0, "job_timeout_s": 600}
JSON
"$bin/rlpos-bench-fill-store" "$work/campaign.json" "$work/rlpos.db"
id=$("$bin/rlpos-campaign" status --db "$work/rlpos.db" | sed -n 's/^campaign \([0-9a-f]*\).*/\1/p' | head -1)
[ -n "$id" ] || id=$(sqlite3 "$work/rlpos.db" "SELECT id FROM campaigns LIMIT 1")
echo "database: $(du -h "$work/rlpos.db" | cut -f1), campaign $id"

"$bin/rlpos-campaign" serve --db "$work/rlpos.db" --listen 127.0.0.1:0 >"$work/serve.txt" &
serve_pid=$!
for _ in $(seq 100); do grep -q '^serving ' "$work/serve.txt" && break; sleep 0.1; done
url=$(sed -n 's/^serving .* on \(http[^ ]*\).*/\1/p' "$work/serve.txt")
[ -n "$url" ] || { echo "serve did not start" >&2; exit 1; }
rss() { awk -v k="$1:" '$1 == k {print $2 / 1024 " MiB"}' "/proc/$serve_pid/status"; }
echo "serve RSS at start: $(rss VmRSS)"

median() { sort -n | awk '{v[NR] = $1} END {print v[int((NR + 1) / 2)]}'; }
for path in api/campaigns "api/campaigns/$id" "api/campaigns/$id/distributions" \
  "api/campaigns/$id/learning-curves" "api/campaigns/$id/maps"; do
  ms=$(for _ in 1 2 3 4 5; do
    curl -s -o "$work/body" -w '%{time_total}\n' "$url$path" | awk '{print $1 * 1000}'
  done | median)
  printf "api ms  %-48s %8.1f  (%s bytes)\n" "/$path" "$ms" "$(wc -c <"$work/body")"
done

/usr/bin/python3 - "$url" "$id" <<'PY'
import os, statistics, sys, tempfile, time
from selenium import webdriver
from selenium.webdriver.chrome.service import Service
url, campaign = sys.argv[1], sys.argv[2]
options = webdriver.ChromeOptions()
options.binary_location = "/usr/bin/chromium"
profile = tempfile.mkdtemp(prefix="rlpos-chromium-")
for flag in ("--headless=new", "--disable-gpu", "--window-size=1400,1000", f"--user-data-dir={profile}"):
    options.add_argument(flag)
if os.geteuid() == 0:
    options.add_argument("--no-sandbox")
driver = webdriver.Chrome(service=Service("/usr/bin/chromedriver"), options=options)
try:
    loads = []
    for _ in range(3):
        driver.get("about:blank")
        driver.get(f"{url}#/campaign/{campaign}")
        deadline = time.monotonic() + 120
        mark = None
        while mark is None and time.monotonic() < deadline:
            mark = driver.execute_script(
                "const m = performance.getEntriesByName('rlpos-plotted'); return m.length ? m[0].startTime : null")
            time.sleep(0.05)
        if mark is None:
            sys.exit("the campaign view was never drawn")
        loads.append(mark)
    print("page ms navigation to campaign view drawn: median %.0f (loads: %s)"
          % (statistics.median(loads), ", ".join("%.0f" % v for v in loads)))
finally:
    driver.quit()
PY
echo "serve RSS after the loads: $(rss VmRSS), peak $(rss VmHWM)"
