#!/usr/bin/env bash
# tools/benchmarks/sky_cost.sh OLD_BUILD [ROUNDS]: the sky pass's and the frame's time at 800x600 in
# an older build (OLD_BUILD: its build folder, with its shaders) and in this tree's, interleaved,
# for pool, ocean, lake and the showcase lagoon (`vkwater render --repeat 2`, frame 2's pass list).
# Prints one line per render: scene, build (old or new), round, sky ms, frame ms, calibration ms.
# Made for docs/performance.md, "The sky over only what nothing covers".
set -euo pipefail
cd "$(dirname "$0")/../.."
[ $# -ge 1 ] && [ -x "$1/tools/vkwater/vkwater" ] || { echo "usage: $0 OLD_BUILD [ROUNDS]" >&2; exit 1; }
old=$1
rounds=${2:-3}
source tools/benchmarks/provenance.sh
provenance_start
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
for round in $(seq "$rounds"); do
  for scene in pool ocean lake showcase/lagoon; do
    for build in "$old" build; do
      tag=$([ "$build" = build ] && echo new || echo old)
      VKWATER_SHADER_DIR=$build/shaders "$build/tools/vkwater/vkwater" render "scenes/$scene.json" --width 800 \
        --height 600 --repeat 2 --out "$out/frame.exr" 2>&1 |
        awk -v s="$scene" -v t="$tag" -v r="$round" \
          '/^  sky /{sky=$2} /^  frame /{f=$2} /^  calibration /{c=$2} END{print s, t, r, sky, f, c}'
    done
  done
done
provenance_line build/tools/vkwater/vkwater "old build: $old"
