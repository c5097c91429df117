#!/usr/bin/env bash
# setting_ratio.sh ROUNDS SCENE SETTING [SETTING ...]
#
# Several settings of one scene, with this tree's build, interleaved: each round renders the scene
# once per SETTING (a quoted string of `vkwater render` options, "" for the scene's own), the
# first setting of each round rotating, and each figure is the median over the rounds. A pass's
# time is printed in ms and in calibration units of the same frame (the calibration pass, a
# constant shader over every pixel: the 2x swings of a shared machine cancel in it). Fence-timed on
# CPU devices, GPU timestamps elsewhere. WIDTH and HEIGHT (default 800x600) and REPEAT (frames per
# render, the last one timed; default 2) set what is rendered; VKWATER the binary. Prints a
# Markdown table, one row per pass and one column pair per setting, then where it comes from.
#
#   tools/benchmarks/setting_ratio.sh 3 pool "" "--set effects.caustics.kernel=bilinear"
set -euo pipefail
cd "$(dirname "$0")/../.."
source "$(dirname "$0")/provenance.sh"
provenance_start
[ $# -ge 3 ] || { echo "usage: tools/benchmarks/setting_ratio.sh ROUNDS SCENE SETTING [SETTING ...]" >&2; exit 1; }
rounds=$1 scene=$2
shift 2
settings=("$@")
vk=${VKWATER:-build/tools/vkwater/vkwater}
width=${WIDTH:-800} height=${HEIGHT:-600} repeat=${REPEAT:-2}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

for round in $(seq 1 "$rounds"); do
  for k in $(seq 0 $((${#settings[@]} - 1))); do
    i=$(((k + round - 1) % ${#settings[@]}))
    read -r -a options <<< "${settings[$i]}"
    "$vk" render "scenes/$scene.json" --width "$width" --height "$height" --repeat "$repeat" "${options[@]}" \
      --out "$work/frame.exr" 2> /dev/null |
      awk -v prefix="$i	$round" -v skip_declare=1 -f tools/benchmarks/pass_times.awk
  done
done > "$work/times.tsv"

names=$(printf '%s\n' "${settings[@]}" | awk '{ printf "%s%s", (NR > 1 ? "\t" : ""), ($0 == "" ? "the scene'"'"'s own" : $0) }')
awk -F'\t' -v names="$names" '
  { ms[$1, $2, $3] = $4; if ($3 == "calibration") cal[$1, $2] = $4; rounds[$2] = 1
    if (!($3 in seen)) { seen[$3] = 1; order[++count] = $3 } }
  function median(values, n,    i, j, t) {
    for (i = 2; i <= n; i++) for (j = i; j > 1 && values[j - 1] > values[j]; j--) { t = values[j]; values[j] = values[j - 1]; values[j - 1] = t }
    return n % 2 ? values[(n + 1) / 2] : (values[n / 2] + values[n / 2 + 1]) / 2
  }
  function figure(s, pass, in_cal,    r, n, v) {
    n = 0; delete v
    for (r in rounds) if ((s, r, pass) in ms) v[++n] = in_cal ? ((s, r) in cal && cal[s, r] > 0 ? ms[s, r, pass] / cal[s, r] : -1) : ms[s, r, pass]
    return n ? sprintf("%.1f", median(v, n)) : "-"
  }
  END {
    settings = split(names, name, "\t")
    header = "| pass |"; rule = "| --- |"
    for (s = 1; s <= settings; s++) { header = header " " name[s] ", ms | cal |"; rule = rule " --- | --- |" }
    print header; print rule
    for (i = 1; i <= count; i++) {
      row = "| " order[i] " |"
      for (s = 1; s <= settings; s++) row = row " " figure(s - 1, order[i], 0) " | " figure(s - 1, order[i], 1) " |"
      print row
    }
  }' "$work/times.tsv"
provenance_line "$vk" "$scene at ${width}x$height, medians of $rounds interleaved rounds"
