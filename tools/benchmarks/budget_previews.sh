#!/usr/bin/env bash
# tools/benchmarks/budget_previews.sh [SCENE...]: what the budget's previews measure for its on/off
# knobs (tools/vkwater/budget_previews.hpp) against what the committed error sweep measured for the
# same knob against the scene's reference (docs/sweeps/budget_error_terms.csv, 400x300). For each
# scene, `vkwater render --budget-ms` with a budget every frame meets prints the previews' line;
# prints a Markdown table (scene, knob, preview, sweep, preview / sweep) under a provenance line.
# Errors only: the machine's load does not change them. About 10-20 s a scene on lavapipe.
# Default scenes: the sweep's six (it has no row for the caustics off: "-"). VKWATER=PATH for another
# build.
#
#   tools/benchmarks/budget_previews.sh lake box
set -euo pipefail
cd "$(dirname "$0")/../.."
vk=${VKWATER:-build/tools/vkwater/vkwater}
csv=docs/sweeps/budget_error_terms.csv
source tools/benchmarks/provenance.sh
provenance_start
scenes=("$@")
[ ${#scenes[@]} -gt 0 ] || scenes=(pool lake ocean box showcase/pool showcase/lagoon)
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT

echo "| scene | turned off | previews' relMSE | the sweep's excess | previews / sweep |"
echo "| --- | --- | --- | --- | --- |"
for scene in "${scenes[@]}"; do
    line=$("$vk" render "scenes/$scene.json" --width 400 --height 300 --budget-ms 100000 --out "$out/frame.exr" \
        2>/dev/null | grep '^budget: turned off in' || true)
    [ -n "$line" ] || { echo "budget_previews.sh: $scene: no previews (it runs no on/off knob)" >&2; continue; }
    for pair in "reflection lookup:reflection_lookup" "refraction lookup:refraction_lookup" \
        "refraction view's second layer:second_layer" "caustics:caustics"; do
        name=${pair%%:*} knob=${pair#*:}
        preview=$(sed -n "s/.*[:,] the $name \([^,( ]*\).*/\1/p" <<< "$line")
        [ -n "$preview" ] || continue
        sweep=$(awk -F, -v s="$scene" -v k="$knob" '$1 == s && $2 == k && $3 == 0 { print $5 }' "$csv")
        awk -v s="$scene" -v n="$name" -v p="$preview" -v w="${sweep:-}" 'BEGIN {
            ratio = (w == "" ? "no sweep row" : (w + 0 > 0 ? sprintf("%.2f", p / w) : (p + 0 == 0 ? "both 0" : "sweep 0")))
            printf "| %s | %s | %s | %s | %s |\n", s, n, p, (w == "" ? "-" : w), ratio }'
    done
done
echo
echo "*$(provenance_line "$vk" "previews at 160x120 (400x300's aspect); errors only")*"
