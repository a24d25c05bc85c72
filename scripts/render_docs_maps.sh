#!/usr/bin/env bash
# Renders the maps of the shipped scenarios that docs/maps.md shows: the top view of each
# campaigns/scenarios/*.json at its baseline, and scenario C with its elevation views.
# Usage: scripts/render_docs_maps.sh [BUILD_DIR] [OUT_DIR]   (defaults: build, docs/maps)
# tests/docs (ctest -R docs.maps) renders them again and fails when a committed map differs.
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
build_dir=${1:-"$here/build"}
out_dir=${2:-"$here/docs/maps"}
sim="$build_dir/bin/rlpos-sim"
[ -x "$sim" ] || { echo "render_docs_maps: $sim not found: build rlpos-sim first" >&2; exit 1; }
mkdir -p "$out_dir"
for scenario in "$here"/campaigns/scenarios/*.json; do
  name=$(basename "$scenario" .json)
  "$sim" render "$scenario" --out "$out_dir/$name.svg" >/dev/null
done
"$sim" render "$here/campaigns/scenarios/c.json" --side --out "$out_dir/c_side.svg" >/dev/null
echo "render_docs_maps: $(ls "$out_dir"/*.svg | wc -l) maps in $out_dir"
