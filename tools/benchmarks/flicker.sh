#!/usr/bin/env bash
# tools/benchmarks/flicker.sh SCENE [FRAMES] [FPS] [WxH] [CSV]: how much the real-time image flickers with
# the clock running at a fixed camera, against the reference's own change over the same frames.
# Renders FRAMES frames (default 32) at FPS (default 24) with `vkwater render --frames`, once as
# they are and once with temporal accumulation (`--temporal`), and the reference of each frame
# (`vkwater reference --set water.time=...`, the scene's time plus f / FPS), at WxH (default
# 400x300); then, for each pair of consecutive frames of each sequence, the relMSE of the later
# against the earlier (`vkwater compare`), and of each real-time frame against its reference.
# Prints one row per pair and the means of each sequence, and with CSV given writes the rows there
# under a line that says when, at which commit and on which device they were measured
# (docs/sweeps/flicker-*.csv). The reference's frame-to-frame relMSE is the change the scene really
# has; the real-time one above it is flicker (docs/accuracy.md). Costs FRAMES references: about
# 4 min for pool at 400x300 on 2 cores, 55 min for ocean at 200x150.
set -euo pipefail
cd "$(dirname "$0")/../.."
scene=${1:?usage: tools/benchmarks/flicker.sh SCENE [FRAMES] [FPS] [WxH]}
frames=${2:-32}
fps=${3:-24}
size=${4:-400x300}
csv=${5:-}
width=${size%x*}
height=${size#*x}
vk=${VKWATER:-build/tools/vkwater/vkwater}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
source tools/benchmarks/provenance.sh
provenance_start
"$vk" render "$scene" --frames "0:$((frames - 1))" --fps "$fps" --width "$width" --height "$height" \
    --out "$out/rt_%04d.exr" -q
mkdir -p "$out/temporal"
"$vk" render "$scene" --frames "0:$((frames - 1))" --fps "$fps" --width "$width" --height "$height" --temporal \
    --out "$out/temporal/rt_%04d.exr" -q
start=$(python3 -c 'import json, sys; print(json.load(open(sys.argv[1]))["water"].get("time", 0))' "$scene")
for ((f = 0; f < frames; ++f)); do
    t=$(python3 -c "print(repr($start + $f / $fps))")
    "$vk" reference "$scene" --set "water.time=$t" --width "$width" --height "$height" \
        --out "$(printf "$out/ref_%04d.exr" "$f")" -q
done
relmse() { "$vk" compare "$1" "$2" | awk '/^relMSE/ {print $2; exit}'; }
echo "pair,real_time_change,reference_change,real_time_error,temporal_change,temporal_error"
for ((f = 1; f < frames; ++f)); do
    a=$(printf "%04d" $((f - 1)))
    b=$(printf "%04d" "$f")
    echo "$((f - 1))-$f,$(relmse "$out/rt_$b.exr" "$out/rt_$a.exr"),$(relmse "$out/ref_$b.exr" "$out/ref_$a.exr"),$(relmse "$out/rt_$b.exr" "$out/ref_$b.exr"),$(relmse "$out/temporal/rt_$b.exr" "$out/temporal/rt_$a.exr"),$(relmse "$out/temporal/rt_$b.exr" "$out/ref_$b.exr")"
done | tee "$out/pairs.csv"
awk -F, '{rt += $2; ref += $3; err += $4; t += $5; terr += $6; n++} END {
    printf "mean: real-time change %.5g, reference change %.5g, ratio %.3f; real-time error %.5g\n", rt / n, ref / n, rt / ref, err / n
    printf "mean with --temporal: change %.5g, ratio %.3f; error %.5g\n", t / n, t / ref, terr / n }' "$out/pairs.csv"
if [ -n "$csv" ]; then
    {
        echo "# $(provenance_line "$vk" "$scene, $frames frames at $fps fps, ${width}x${height}; errors only, which the load does not change")"
        echo "pair,real_time_change,reference_change,real_time_error,temporal_change,temporal_error"
        cat "$out/pairs.csv"
    } > "$csv"
    echo "wrote $csv"
fi
