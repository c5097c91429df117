#!/usr/bin/env bash
# array_wall_time.sh [BUILD_DIR] [FRAMES] [TASKS] [ROUNDS] [SCENE]
#
# The wall time of a sequence rendered by a Slurm job array of TASKS tasks against one process, on
# a single-node Slurm started on this machine (tools/slurm/local_cluster.sh; needs root, slurm-wlm
# and munge). Each round renders FRAMES frames of SCENE at 400x300 both ways, alternating which goes
# first. The array's time runs from sbatch until its last frame is recorded (the manifest's last
# write: sbatch --wait itself polls at 2, 10, 18, ... s, which would round it up). Medians over the
# rounds. Defaults: build, 48, 4, 2, pool. Prints a Markdown table (docs/sequences.md keeps one).
set -euo pipefail
cd "$(dirname "$0")/../.."
source "$(dirname "$0")/provenance.sh"
provenance_start
build=${1:-build}
frames=${2:-48}
tasks=${3:-4}
rounds=${4:-2}
scene=${5:-pool}
vk=$(pwd)/$build/tools/vkwater/vkwater
[ -x "$vk" ] || { echo "array_wall_time: build first ($vk)" >&2; exit 1; }

# shellcheck source=../slurm/local_cluster.sh
source tools/slurm/local_cluster.sh
scratch=$(mktemp -d)
trap 'stop_local_slurm; rm -rf "$scratch"' EXIT
trap 'exit 143' TERM INT
start_local_slurm
size=(--width 400 --height 300)

now() { date +%s.%N; }

one_process() {
  local out=$scratch/one-$1 start end
  start=$(now)
  "$vk" render "scenes/$scene.json" "${size[@]}" --frames "0:$((frames - 1))" --out "$out/f_%04d.exr" -q
  end=$(now)
  awk -v a="$start" -v b="$end" 'BEGIN { print b - a }'
}

array() {
  local out=$scratch/array-$1 start
  mkdir -p "$scratch/logs"
  start=$(now)
  VKWATER=$vk sbatch --wait --quiet --array=0-$((tasks - 1)) --output="$scratch/logs/$1-%a.out" \
    tools/slurm/render_sequence.sbatch "scenes/$scene.json" "0:$((frames - 1))" "$out/f_%04d.exr" "${size[@]}" > /dev/null
  awk -v a="$start" -v b="$(stat -c %.9Y "$out/manifest.json")" 'BEGIN { print b - a }'
}

one=() arr=()
for ((round = 0; round < rounds; ++round)); do
  if ((round % 2 == 0)); then
    one+=("$(one_process "$round")")
    arr+=("$(array "$round")")
  else
    arr+=("$(array "$round")")
    one+=("$(one_process "$round")")
  fi
done

source tools/benchmarks/median.sh
provenance_line "$vk"
echo "| scene | size | frames | one process, s | array of $tasks tasks, s | array / one | rounds | CPUs |"
echo "| --- | --- | --- | --- | --- | --- | --- | --- |"
awk -v scene="$scene" -v frames="$frames" -v one="$(printf '%s\n' "${one[@]}" | median)" -v arr="$(printf '%s\n' "${arr[@]}" | median)" \
  -v rounds="$rounds" -v cpus="$(nproc)" 'BEGIN {
  printf "| %s | 400x300 | %d | %.1f | %.1f | %.2f | %d | %d |\n", scene, frames, one, arr, arr / one, rounds, cpus
}'
