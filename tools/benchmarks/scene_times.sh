#!/usr/bin/env bash
# scene_times.sh [ROUNDS] [WIDTHxHEIGHT ...]
#
# Every built-in scene at each size, with this tree's build (build/tools/vkwater/vkwater, or
# VKWATER=PATH), on the default device (a discrete GPU first; --device through DEVICE=TEXT).
# Each round renders every scene once at every size with `vkwater render --repeat FRAMES`
# (FRAMES=20 by default) and takes the last frame's pass times: GPU timestamp queries on a GPU,
# one fence per pass on lavapipe. Each figure is the median over the rounds.
#
# Prints two Markdown tables: per scene and size, the frame (the submission's wall time, the
# readback of the image included), the sum of the passes, the calibration pass (a constant
# shader over every pixel: the cheapest full-screen pass, the unit that makes two machines
# comparable), the graph's CPU declare + compile, and the three costliest passes; then every
# pass of every scene at the last size. docs/performance.md keeps the tables. With CSV=FILE, also
# writes per scene and size the frame, the passes' sum, the calibration pass and the graph's CPU time
# (ms) to FILE, under a first line that says where they come from (docs/sweeps/gpu-scene-times.csv,
# which the README's headline table reads, is such a file).
set -euo pipefail
cd "$(dirname "$0")/../.."
source "$(dirname "$0")/provenance.sh"
provenance_start

rounds=${1:-3}
shift $(( $# >= 1 ? 1 : 0 ))
sizes=("$@")
[ ${#sizes[@]} -gt 0 ] || sizes=(800x600 1920x1080)
scenes=(${SCENES:-calm pool lake ocean underwater box})
frames=${FRAMES:-20}
vk=${VKWATER:-build/tools/vkwater/vkwater}
[ -x "$vk" ] || { echo "scene_times: build this tree first ($vk)" >&2; exit 1; }
device_args=()
[ -z "${DEVICE:-}" ] || device_args=(--device "$DEVICE")

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# One render's pass lines as "scene size round pass ms"; the device's name goes to device.txt.
run() {
  local scene=$1 size=$2 round=$3
  "$vk" render "scenes/$scene.json" --width "${size%x*}" --height "${size#*x}" --repeat "$frames" \
    "${device_args[@]}" --no-caustic-layer --no-inscatter-layer --out "$work/frame.exr" > "$work/log.txt" 2>&1 ||
    { echo "scene_times: $scene at $size failed:" >&2; cat "$work/log.txt" >&2; exit 2; }
  sed -n 's/^device: \(.*\) (instance.*/\1/p' "$work/log.txt" > "$work/device.txt"
  sed -n 's/^pass times of frame [0-9]* of [0-9]* (\(.*\)):$/\1/p' "$work/log.txt" > "$work/method.txt"
  awk -v prefix="$scene\t$size\t$round" -f tools/benchmarks/pass_times.awk "$work/log.txt"
}

for round in $(seq 1 "$rounds"); do
  for size in "${sizes[@]}"; do
    for scene in "${scenes[@]}"; do run "$scene" "$size" "$round"; done
  done
done > "$work/times.tsv"

provenance_line "$vk"
echo "device: $(cat "$work/device.txt"); timing: $(cat "$work/method.txt"); frame $frames of \`--repeat $frames\`, median of $rounds rounds"
echo
csv=${CSV:-}
if [ -n "$csv" ]; then
  {
    echo "# $(provenance_line "$vk" "device: $(cat "$work/device.txt"); timing: $(cat "$work/method.txt"); frame $frames of --repeat $frames, median of $rounds rounds")"
    echo "scene,size,frame_ms,passes_ms,calibration_ms,graph_cpu_ms"
  } > "$csv"
fi
awk -F'\t' -v last_size="${sizes[${#sizes[@]}-1]}" -v scene_list="${scenes[*]}" -v size_list="${sizes[*]}" -v csv="$csv" '
  { ms[$1, $2, $3, $4] = $5; rounds[$3] = 1
    if (!(($1, $4) in seen)) { seen[$1, $4] = 1; order[$1, ++count[$1]] = $4 } }
  function median(values, n,    i, j, t) {
    for (i = 2; i <= n; i++) for (j = i; j > 1 && values[j - 1] > values[j]; j--) { t = values[j]; values[j] = values[j - 1]; values[j - 1] = t }
    return n % 2 ? values[(n + 1) / 2] : (values[n / 2] + values[n / 2 + 1]) / 2
  }
  function med(scene, size, pass,    r, n, v) {
    n = 0; delete v
    for (r in rounds) if ((scene, size, r, pass) in ms) v[++n] = ms[scene, size, r, pass]
    return n ? median(v, n) : -1
  }
  function pass_sum(scene, size,    i, p, total) {
    total = 0
    for (i = 1; i <= count[scene]; i++) { p = order[scene, i]
      if (p != "frame" && p !~ /^declare/ && med(scene, size, p) >= 0) total += med(scene, size, p) }
    return total
  }
  function fmt(x) { return x < 0 ? "-" : x < 10 ? sprintf("%.3f", x) : sprintf("%.1f", x) }
  END {
    ns = split(scene_list, scene_names, " "); nz = split(size_list, size_names, " ")
    print "| scene | size | frame ms | fps | passes ms | calibration ms | graph CPU ms | costliest passes (ms) |"
    print "| --- | --- | --- | --- | --- | --- | --- | --- |"
    for (z = 1; z <= nz; z++) for (s = 1; s <= ns; s++) {
      scene = scene_names[s]; size = size_names[z]; frame = med(scene, size, "frame")
      # The three costliest passes, by a selection over the median pass times.
      delete taken; top = ""
      for (k = 1; k <= 3; k++) { best = ""; best_ms = -1
        for (i = 1; i <= count[scene]; i++) { p = order[scene, i]
          if (p == "frame" || p ~ /^declare/ || (p in taken)) continue
          t = med(scene, size, p); if (t > best_ms) { best_ms = t; best = p } }
        if (best != "") { taken[best] = 1; top = top (k > 1 ? ", " : "") best " " fmt(best_ms) } }
      print "| " scene " | " size " | " fmt(frame) " | " (frame > 0 ? sprintf("%.0f", 1000 / frame) : "-") " | " \
            fmt(pass_sum(scene, size)) " | " fmt(med(scene, size, "calibration")) " | " \
            fmt(med(scene, size, "declare + compile graph")) " | " top " |"
      if (csv != "") print scene "," size "," frame "," pass_sum(scene, size) "," med(scene, size, "calibration") "," \
                           med(scene, size, "declare + compile graph") >> csv
    }
    print ""
    print "| scene | pass | ms at " last_size " |"
    print "| --- | --- | --- |"
    for (s = 1; s <= ns; s++) { scene = scene_names[s]
      for (i = 1; i <= count[scene]; i++) { p = order[scene, i]
        if (p ~ /^declare/) continue
        print "| " scene " | " p " | " fmt(med(scene, last_size, p)) " |" } }
  }' "$work/times.tsv"
