#!/usr/bin/env bash
# slurm_array_test.sh SOURCE_DIR VKWATER
#
# A sequence rendered by a Slurm job array (tools/slurm/render_sequence.sbatch, 4 tasks, one
# shard of the frames each, all writing one folder) must equal the same sequence rendered by one
# process: every frame file in both, bit-identical pixels, and one merged manifest.json listing
# exactly the frames, with the single run's pixel hashes. The cluster is a single-node Slurm
# started for the test in a temporary folder (tools/slurm/local_cluster.sh) and stopped on exit.
#
# Exits 77 (skipped), saying why, when not root or when slurm-wlm or munge is missing or the local
# cluster does not start: slurmd runs jobs as their user, which needs root.
set -euo pipefail
source_dir=$(cd "$1" && pwd)
vk=$(cd "$(dirname "$2")" && pwd)/$(basename "$2")
frames=16

skip() {
  echo "SKIPPED: $*"
  exit 77
}
fail() {
  echo "FAIL: $*" >&2
  exit 1
}
now() { date +%s.%N; }
seconds_since() { awk -v a="$1" -v b="$(now)" 'BEGIN { printf "%.1f", b - a }'; }

[ "$(id -u)" -eq 0 ] || skip "needs root to run a local Slurm (slurmd starts jobs as their user); running as $(id -un)"
for tool in slurmctld slurmd sbatch munged mungekey idiff oiiotool python3 timeout; do
  command -v "$tool" > /dev/null || skip "$tool not found (tools/install-deps.sh installs slurm-wlm, munge and openimageio-tools)"
done

# shellcheck source-path=SCRIPTDIR source=../../tools/slurm/local_cluster.sh
source "$source_dir/tools/slurm/local_cluster.sh"
tmp=$(mktemp -d -t vkwater-slurm-test.XXXXXX)
# The daemons must not outlive the test, also when ctest's timeout or ^C ends it: a signal without
# its own trap would end bash without running the EXIT trap.
trap 'stop_local_slurm; rm -rf "$tmp"' EXIT
trap 'exit 143' TERM INT

start=$(now)
start_local_slurm 2> "$tmp/start.txt" || skip "the local Slurm cluster did not start: $(tr '\n' ' ' < "$tmp/start.txt")"
echo "local Slurm up in $(seconds_since "$start") s ($SLURM_CONF)"

cd "$source_dir"  # the scene's path is relative, and the array's tasks start in sbatch's folder
size=(--width 64 --height 48)

# The array: sbatch passes this shell's environment (VKWATER, VKWATER_SHADER_DIR) to the tasks.
# --wait returns the highest exit code of its tasks. The timeouts here end a wait on tasks that
# never run, or a hung render, while the EXIT trap can still stop the daemons: ctest's TIMEOUT kills
# the test with SIGKILL, which no trap sees.
mkdir "$tmp/logs"
start=$(now)
status=0
VKWATER=$vk timeout 180 sbatch --wait --array=0-3 --output="$tmp/logs/task-%a.out" \
  tools/slurm/render_sequence.sbatch scenes/pool.json "0:$((frames - 1))" "$tmp/array/f_%04d.exr" "${size[@]}" ||
  status=$?
array_s=$(seconds_since "$start")
for ((task = 0; task < 4; ++task)); do
  echo "--- task $task:"
  cat "$tmp/logs/task-$task.out" 2>/dev/null || echo "(no output file)"
done
[ "$status" -ne 124 ] || fail "the array did not finish within 180 s: $(squeue --noheader 2>&1 | tr '\n' ' ')"
[ "$status" -eq 0 ] || fail "sbatch --wait exited $status: a task failed (output above)"

# Each task rendered its quarter of the frames, not all of them (sacct needs accounting, which the
# local cluster has not; sbatch --wait's status above is the tasks' highest exit code).
for ((task = 0; task < 4; ++task)); do
  grep -q "render_sequence: task $task/4" "$tmp/logs/task-$task.out" || fail "task $task's output does not name shard $task/4"
  grep -q "rendered $((frames / 4)) frame(s)" "$tmp/logs/task-$task.out" || fail "task $task did not render $((frames / 4)) frames"
done

start=$(now)
timeout 120 "$vk" render scenes/pool.json --frames "0:$((frames - 1))" "${size[@]}" --out "$tmp/single/f_%04d.exr" -q
single_s=$(seconds_since "$start")

# idiff -fail 0 -failpercent 0 -warn 0 fails on any difference in any channel of any pixel, and
# compares pixels only, not the attributes (the frame's time differs from run to run). Checked
# with OpenImageIO 2.4.7: one value one float step apart (caustic.B 132.5727 against 132.57271)
# fails, as does 1e-7 added to one channel of one pixel, while a changed attribute passes, and
# idiff's defaults (-fail 1e-6) pass the 1e-7 change. The first check below repeats the 1e-7 case
# on this run's first frame, so that an idiff comparing less fails this test rather than passing it.
same_pixels() { idiff -fail 0 -failpercent 0 -warn 0 "$1" "$2" > "$tmp/idiff.txt" 2>&1; }

one_value_changed() {  # SRC DST: SRC with 1e-7 added to the first channel of pixel (0, 0)
  local channels width height color i
  read -r channels width height < <(oiiotool "$1" --echo "{TOP.nchannels} {TOP.width} {TOP.height}")
  color=1e-7
  for ((i = 1; i < channels; ++i)); do color+=,0; done
  oiiotool "$1" --pattern constant:color=0 "${width}x$height" "$channels" --fill:color="$color" 1x1+0+0 \
    --add -d float -o "$2"
}
one_value_changed "$tmp/single/f_0000.exr" "$tmp/changed.exr"
! same_pixels "$tmp/single/f_0000.exr" "$tmp/changed.exr" || fail "idiff does not see one value changed by 1e-7"

for ((frame = 0; frame < frames; ++frame)); do
  name=$(printf 'f_%04d.exr' "$frame")
  [ -f "$tmp/array/$name" ] || fail "the array did not write $name"
  [ -f "$tmp/single/$name" ] || fail "the single process did not write $name"
  same_pixels "$tmp/array/$name" "$tmp/single/$name" || fail "$name differs: $(cat "$tmp/idiff.txt")"
done

python3 - "$tmp/array/manifest.json" "$tmp/single/manifest.json" "$frames" <<'EOF'
import json, sys
array, single = (json.load(open(p)) for p in sys.argv[1:3])
expected = list(range(int(sys.argv[3])))
for name, m in (("array", array), ("single", single)):
    got = [f["frame"] for f in m["frames"]]
    if got != expected:
        sys.exit(f"FAIL: the {name} manifest lists frames {got}, not 0..{expected[-1]}")
for a, s in zip(array["frames"], single["frames"]):
    if (a["file"], a["pixelHash"]) != (s["file"], s["pixelHash"]):
        sys.exit(f"FAIL: frame {a['frame']}: array {a['file']} {a['pixelHash']}, single {s['file']} {s['pixelHash']}")
EOF

echo "array of 4 tasks: $array_s s; one process: $single_s s; $frames frames identical, one manifest"
