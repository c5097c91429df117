#!/usr/bin/env bash
# tools/benchmarks/sky_cost.sh OLD_BUILD [ROUNDS]: the sky pass, the water pass and the frame at
# 800x600 in an older build (OLD_BUILD: its build folder, with its shaders) and in this tree's,
# interleaved, for pool, ocean, lake and the showcase lagoon (`vkwater render --repeat 2`, frame 2's
# pass list; default 3 rounds). The water pass is there because, with the sky drawn last, the first
# opaque pass (the water, in these scenes) creates the colour target and clears it. Prints the
# provenance line and a Markdown table of the medians over the rounds (ms).
# Made for docs/performance.md, "The sky over only what nothing covers".
set -euo pipefail
cd "$(dirname "$0")/../.."
[ $# -ge 1 ] && [ -x "$1/tools/vkwater/vkwater" ] || { echo "usage: $0 OLD_BUILD [ROUNDS]" >&2; exit 1; }
old=$1
rounds=${2:-3}
scenes=(pool ocean lake showcase/lagoon)
source tools/benchmarks/provenance.sh
source tools/benchmarks/median.sh
provenance_start
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
for round in $(seq "$rounds"); do
  for scene in "${scenes[@]}"; do
    for build in "$old" build; do
      tag=$([ "$build" = build ] && echo new || echo old)
      VKWATER_SHADER_DIR=$build/shaders "$build/tools/vkwater/vkwater" render "scenes/$scene.json" --width 800 \
        --height 600 --repeat 2 --out "$out/frame.exr" 2>&1 |
        awk '/^  sky /{sky=$2} /^  water /{water=$2} /^  frame /{frame=$2} END{print sky, water, frame}' \
          >>"$out/$(echo "$scene" | tr / _).$tag"
    done
  done
done
provenance_line build/tools/vkwater/vkwater "old build: $old; median of $rounds rounds"
echo
echo "| scene | sky before | sky now | water before | water now | frame before | frame now |"
echo "| --- | --- | --- | --- | --- | --- | --- |"
for scene in "${scenes[@]}"; do
  name=$(echo "$scene" | tr / _)
  row="| $scene"
  for column in 1 2 3; do
    for tag in old new; do row="$row | $(awk -v c=$column '{ print $c }' "$out/$name.$tag" | median)"; done
  done
  echo "$row |"
done
