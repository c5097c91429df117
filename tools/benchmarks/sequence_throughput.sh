#!/usr/bin/env bash
# sequence_throughput.sh [BUILD_DIR] [FRAMES] [ROUNDS] [SCENE]
#
# What rendering a sequence in one process saves over one frame per process (the device, the
# pipelines and the frame's device objects made once): each round renders FRAMES frames of SCENE
# at 400x300 in one `vkwater render --frames` process, and FRAMES/10 frames of the same range
# (every tenth) in one process each; the table gives each way's wall time per frame (median over
# the rounds, the two ways alternating which goes first) and their ratio. Wall times, so a shared
# machine's load moves both; the ratio is the figure to read. Defaults: build, 240, 2, pool.
# Prints a Markdown table (docs/sequences.md keeps one).
set -euo pipefail
cd "$(dirname "$0")/../.."
source "$(dirname "$0")/provenance.sh"
provenance_start
build=${1:-build}
frames=${2:-240}
rounds=${3:-2}
scene=${4:-pool}
vk=$build/tools/vkwater/vkwater
[ -x "$vk" ] || { echo "sequence_throughput: build first ($vk)" >&2; exit 1; }
(( frames >= 10 )) || { echo "sequence_throughput: FRAMES must be 10 or more" >&2; exit 1; }
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
size=(--width 400 --height 300)

now() { date +%s.%N; }

one_process() {  # prints seconds per frame
  local out=$scratch/one-$1
  rm -rf "$out"
  local start end
  start=$(now)
  "$vk" render "scenes/$scene.json" "${size[@]}" --frames "0:$((frames - 1))" --out "$out/f_%04d.exr" -q
  end=$(now)
  awk -v a="$start" -v b="$end" -v n="$frames" 'BEGIN { print (b - a) / n }'
}

process_per_frame() {  # prints seconds per frame
  local out=$scratch/each-$1 count=0 frame start end
  rm -rf "$out"
  start=$(now)
  for ((frame = 0; frame < frames; frame += 10)); do
    "$vk" render "scenes/$scene.json" "${size[@]}" --frames "$frame:$frame" --out "$out/f_%04d.exr" -q
    count=$((count + 1))
  done
  end=$(now)
  awk -v a="$start" -v b="$end" -v n="$count" 'BEGIN { print (b - a) / n }'
}

one=() each=()
for ((round = 0; round < rounds; ++round)); do
  if ((round % 2 == 0)); then
    one+=("$(one_process "$round")")
    each+=("$(process_per_frame "$round")")
  else
    each+=("$(process_per_frame "$round")")
    one+=("$(one_process "$round")")
  fi
done

source tools/benchmarks/median.sh
one_s=$(printf '%s\n' "${one[@]}" | median)
each_s=$(printf '%s\n' "${each[@]}" | median)
device=$("$vk" render "scenes/calm.json" --width 8 --height 8 --out "$scratch/probe.exr" | sed -n 's/^device: \(.*\) (instance.*/\1/p')
provenance_line "$vk"
echo "| scene | size | one process, $frames frames: s per frame (fps) | one process per frame, $((frames / 10)) frames: s per frame (fps) | ratio | rounds | device |"
echo "| --- | --- | --- | --- | --- | --- | --- |"
awk -v scene="$scene" -v one="$one_s" -v each="$each_s" -v rounds="$rounds" -v device="$device" 'BEGIN {
  printf "| %s | 400x300 | %.3f (%.2f) | %.3f (%.2f) | %.2f | %d | %s |\n", scene, one, 1 / one, each, 1 / each, each / one, rounds, device
}'
