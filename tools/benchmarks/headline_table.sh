#!/usr/bin/env bash
# headline_table.sh [ROUNDS]
#
# The README's table of the built-in scenes, with where and when it was measured. Per scene:
# - the frame at 800x600: frame 2 of `vkwater render SCENE --repeat 2` (the first frame compiles
#   the pipelines), in ms and in calibration passes of the same frame (the frame's time over its
#   calibration pass, a constant shader over every pixel: the ratio moves far less than the time
#   when the machine is shared). The median over ROUNDS rounds (default 3); each round renders
#   every scene once in turn, so a slow spell of the machine touches every scene alike.
# - the error at 400x300 against the scene's committed reference (tests/references/): relMSE and
#   the caustic layer's relMSE, from one render (a render is deterministic).
# The first line says where the figures come from: the date, the commit (marked when the tree has
# uncommitted changes), the device, the CPU count and the load average before and after.
# - on a GPU, where one has been measured: the frame at 1920x1080 from the committed CSV of
#   tools/benchmarks/scene_times.sh (GPU_CSV, default docs/sweeps/gpu-scene-times.csv; "-" for a
#   scene it lacks), whose first line the second line printed here repeats.
# Uses this tree's build (build/tools/vkwater/vkwater, or VKWATER=PATH); SCENES="pool lake" for
# fewer scenes.
set -euo pipefail
cd "$(dirname "$0")/../.."

rounds=${1:-3}
vk=${VKWATER:-build/tools/vkwater/vkwater}
[ -x "$vk" ] || { echo "headline_table: build this tree first ($vk)" >&2; exit 1; }
scenes=(${SCENES:-pool lake ocean box showcase/pool showcase/lagoon showcase/ocean showcase/shore calm underwater})

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

source tools/benchmarks/provenance.sh
provenance_start

# Frame 2's "frame" and "calibration" lines of the pass list: "<frame ms> <calibration ms>".
frame_and_calibration() {
  awk '/^  frame / { frame = $2 } /^  calibration / { calibration = $2 } END { print frame, calibration }' "$1"
}

for round in $(seq "$rounds"); do
  for scene in "${scenes[@]}"; do
    out="$work/$(echo "$scene" | tr / _).$round"
    "$vk" render "scenes/$scene.json" --width 800 --height 600 --repeat 2 --out "$work/frame.exr" > "$out.txt" 2>&1
    frame_and_calibration "$out.txt" > "$out.times"
  done
done
# A number to three significant digits; anything else (n/a) as it is.
number() { if [[ $1 =~ ^[-+0-9.eE]+$ ]]; then printf '%.3g' "$1"; else printf '%s' "$1"; fi; }
source tools/benchmarks/median.sh

gpu_csv=${GPU_CSV:-docs/sweeps/gpu-scene-times.csv}
# The GPU's frame of SCENE at 1920x1080, from the CSV, or "-".
gpu_frame() {
  [ -f "$gpu_csv" ] || { echo "-"; return; }
  awk -F, -v scene="$1" '!/^#/ && $1 == scene && $2 == "1920x1080" { printf "%.1f", $3; found = 1 }
    END { if (!found) printf "-" }' "$gpu_csv"
}

provenance_line "$vk" "median of $rounds rounds"
[ ! -f "$gpu_csv" ] || echo "The GPU column: $gpu_csv, $(head -1 "$gpu_csv" | sed 's/^# *//')"
echo
echo "| scene | frame at 800x600, ms | frame, calibration passes | relMSE at 400x300 | caustic-layer relMSE | GPU frame at 1920x1080, ms |"
echo "| --- | --- | --- | --- | --- | --- |"
for scene in "${scenes[@]}"; do
  name=$(echo "$scene" | tr / _)
  ms=$(cat "$work/$name".*.times | awk '{ print $1 }' | median)
  passes=$(cat "$work/$name".*.times | awk '$2 > 0 { print $1 / $2 }' | median)
  "$vk" render "scenes/$scene.json" --width 400 --height 300 --out "$work/error.exr" \
    --reference "tests/references/$scene.exr" > "$work/error.txt" 2>&1
  errors=$(sed -n 's/^error against [^:]*: relMSE \([^,]*\),.* caustic relMSE \([^,]*\),.*/\1 \2/p' "$work/error.txt")
  read -r relmse caustic <<< "${errors:-n/a n/a}"
  printf '| `%s` | %.0f | %.0f | %s | %s | %s |\n' "$scene" "$ms" "$passes" "$(number "$relmse")" "$(number "$caustic")" \
    "$(gpu_frame "$scene")"
done
