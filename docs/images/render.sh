#!/usr/bin/env bash
# docs/images/render.sh [BUILD_DIR]: renders every showcase scene (scenes/showcase/*.json) to
# docs/images/showcase-<name>.png at 640x360, box-filtered with 4 samples per pixel (anti-aliased
# edges and grout lines), for the README. Prints each file's size, and fails if one is over
# 300 KB (what the README's pictures may weigh).
set -euo pipefail
cd "$(dirname "$0")/../.."
vk=${1:-build}/tools/vkwater/vkwater
[ -x "$vk" ] || { echo "render.sh: build first ($vk)" >&2; exit 1; }
for scene in scenes/showcase/*.json; do
  name=$(basename "$scene" .json)
  out=docs/images/showcase-$name.png
  "$vk" render "$scene" --width 640 --height 360 --spp 4 --out "$out" -q
  bytes=$(stat -c %s "$out")
  echo "$out: $((bytes / 1024)) KiB"
  [ "$bytes" -le 300000 ] || { echo "render.sh: $out is over 300 KB" >&2; status=1; }
done
exit "${status:-0}"
