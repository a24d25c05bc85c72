#!/usr/bin/env bash
# The Debian package as a cluster node gets it: scripts/package builds rlpos_<version>_amd64.deb,
# `apt-get install` installs it, and from outside any checkout, with no PYTHONPATH and only the
# system's PATH: every program's --version, `rlpos-sim validate` and `position` (rl, the shipped
# policy for any scenario) on a shipped scenario, by path and by name, `import rlpos` and
# `rlpos.make`, and a two-worker mini campaign with the installed programs. Then `apt-get remove`
# leaves none of the package's files. Root only (apt); skipped where a package rlpos is already
# installed (not ours to remove).
# Usage: package.sh BIN_DIR SOURCE_DIR
source "$(dirname "$0")/lib.sh"
[ "$(id -u)" -eq 0 ] || { echo "skipped: installing a package needs root"; exit 77; }
if [ "$(dpkg-query -W -f='${Status}' rlpos 2>/dev/null)" = "install ok installed" ]; then
  echo "skipped: a package rlpos is installed here already"
  exit 77
fi

deb=$("$SRC/scripts/package" "$BIN/.." "$WORK") || fail "scripts/package failed"
# RELEASE+COMMITS.gHASH: the release and the commit it was built from.
[[ "$(basename "$deb")" =~ ^rlpos_[0-9]+\.[0-9]+\.[0-9]+\+[0-9]+\.g[0-9a-f]+(\.dirty)?_amd64\.deb$ ]] ||
  fail "package name $deb"
depends=$(dpkg-deb -f "$deb" Depends)
for lib in libns3 libddsc libtorch libtcmalloc "python3 (<< " python3-numpy; do
  [[ "$depends" == *"$lib"* ]] || fail "Depends has no $lib: $depends"
done
purge() { DEBIAN_FRONTEND=noninteractive apt-get purge -y -qq rlpos >/dev/null 2>&1 || true; }
trap 'purge; cleanup' EXIT
DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends "$deb" >/dev/null ||
  fail "apt-get install $deb failed"
dpkg -L rlpos >"$WORK/files.txt"

# Outside the checkout, as a user of the package: the system's PATH, no PYTHONPATH.
mkdir -p "$WORK/user/home"
cd "$WORK/user"
user() { env -i PATH=/usr/bin:/bin HOME="$WORK/user/home" LANG=C.UTF-8 "$@"; }
for program in rlpos-sim rlpos-worker rlpos-coordinator rlpos-campaign; do
  [ "$(user sh -c "command -v $program")" = /usr/bin/$program ] || fail "$program is not /usr/bin/$program"
  version=$(user $program --version | head -n 1) || fail "$program --version exited $?"
  [[ "$version" =~ ^$program\ [0-9]+\.[0-9]+\.[0-9]+\ \(commit\ [^\)]+\)$ ]] ||
    fail "$program --version: $version"
  [ -s /usr/share/man/man1/$program.1 ] || [ -s /usr/share/man/man1/$program.1.gz ] ||
    fail "no man page for $program"
done
shipped=/usr/share/rlpos/campaigns/scenarios/b.json
user rlpos-sim validate "$shipped" >"$WORK/validate.txt" || fail "validate $shipped exited $?"
grep -q "valid" "$WORK/validate.txt" || fail "validate: $(head -3 "$WORK/validate.txt")"
placement() { user rlpos-sim position "$@" --positioner rl --json; }
placement --scenario "$shipped" --policy /usr/share/rlpos/policies/generalist-1uav \
  >"$WORK/by_path.json" || fail "position by path exited $?"
placement --scenario b --policy generalist-1uav >"$WORK/by_name.json" ||
  fail "position by name exited $?"
"$BIN/rlpos-sim" position --scenario "$SRC/campaigns/scenarios/b.json" --positioner rl --json \
  --policy "$SRC/policies/generalist-1uav" >"$WORK/from_build.json"
cmp -s "$WORK/by_path.json" "$WORK/from_build.json" || fail "the installed placement differs"
cmp -s "$WORK/by_name.json" "$WORK/from_build.json" || fail "the placement by name differs"

user python3 -c "
import rlpos
assert rlpos.__file__.startswith('/usr/lib/python3/dist-packages/rlpos/'), rlpos.__file__
env = rlpos.make('$shipped', fidelity='analytic', seed=1)
observation, info = env.reset(seed=1)
observation, reward, terminated, truncated, info = env.step(0)
assert env.observation_space.contains(observation)
env.close()
" || fail "import rlpos; rlpos.make(...) failed"

# A two-worker campaign of the installed programs: the report's plots need share/rlpos too.
cat >"$WORK/user/mini.json" <<JSON
{"name": "from-the-package", "scenarios": ["$shipped", "/usr/share/rlpos/campaigns/scenarios/c.json"],
 "rng_runs": [1, 2], "positioners": ["baseline", "centroid"],
 "eval": {"duration": 1.5, "warmup": 0.5}, "retries": 0, "job_timeout_s": 300}
JSON
user rlpos-campaign run mini.json --workers 2 --db "$WORK/user/rlpos.db" --tag "$TAG" \
  --no-progress >"$WORK/campaign.txt" 2>&1 || fail "the campaign exited $?: $(tail -3 "$WORK/campaign.txt")"
expect_complete "$WORK/user/rlpos.db" 12  # per scenario: 2 position jobs, 4 evals
ls "$WORK"/user/reports/*/throughput_ccdf_B.png >/dev/null 2>&1 || fail "the report has no plots"

cd "$WORK"
DEBIAN_FRONTEND=noninteractive apt-get remove -y -qq rlpos >/dev/null 2>&1 || fail "apt-get remove failed"
left=$(while read -r path; do
  if [ -f "$path" ] || [ -L "$path" ]; then echo "$path"; fi
done <"$WORK/files.txt")
[ -z "$left" ] || fail "left after apt-get remove: $(echo "$left" | head -3)"
for dir in /usr/share/rlpos /usr/lib/rlpos /usr/lib/python3/dist-packages/rlpos; do
  [ ! -e "$dir" ] || fail "$dir left after apt-get remove"
done
echo "package: $(basename "$deb") installed, used from outside a checkout, and removed clean"
