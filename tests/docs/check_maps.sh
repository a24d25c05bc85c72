#!/usr/bin/env bash
# docs/maps/*.svg are what scripts/render_docs_maps.sh renders now: renders them again into a
# temporary folder and compares the bytes. Usage: check_maps.sh BUILD_DIR SOURCE_DIR
set -euo pipefail
build_dir=$1
source_dir=$2
# The maps' one font; another would change every glyph (bootstrap installs fonts-dejavu-core).
if ! fc-match -f '%{file}\n' "DejaVu Sans" | grep -q 'DejaVuSans.ttf$'; then
  echo "check_maps: \"DejaVu Sans\" resolves to $(fc-match "DejaVu Sans"): install fonts-dejavu-core" >&2
  exit 1
fi
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
"$source_dir/scripts/render_docs_maps.sh" "$build_dir" "$tmp" >/dev/null
status=0
for map in "$tmp"/*.svg; do
  name=$(basename "$map")
  if ! cmp -s "$map" "$source_dir/docs/maps/$name"; then
    echo "check_maps: docs/maps/$name differs from what scripts/render_docs_maps.sh renders now;" \
         "run it and commit the maps" >&2
    status=1
  fi
done
for committed in "$source_dir"/docs/maps/*.svg; do
  [ -e "$tmp/$(basename "$committed")" ] || {
    echo "check_maps: docs/maps/$(basename "$committed") is rendered by nothing" >&2
    status=1
  }
done
exit $status
