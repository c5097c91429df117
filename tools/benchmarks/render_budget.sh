#!/usr/bin/env bash
# tools/benchmarks/render_budget.sh SCENE WxH BUDGET_MS... : what `vkwater render --budget-ms B`
# chooses for one image, with one sample per pixel and with up to 16 (`--spp 16`), and the
# error of each choice against the scene's box-filtered reference (tests/references/box/SCENE.exr,
# 400x300): the image rendered at WxH, box-averaged to 400x300 (box_averaged.sh). Prints a Markdown
# table under a provenance line: budget, most samples, the settings chosen, their measured time
# (the budget's own timed frame) and the relMSE. About a minute per row for pool at 800x600.
# SAMPLES="1" (default "1 16") for the most samples per pixel to try; VKWATER=PATH for another build.
#
#   tools/benchmarks/render_budget.sh pool 800x600 500 1000 2000
set -euo pipefail
cd "$(dirname "$0")/../.."
vk=${VKWATER:-build/tools/vkwater/vkwater}
scene=$1 size=$2
shift 2
width=${size%x*} height=${size#*x}
reference=tests/references/box/$scene.exr
[ -f "$reference" ] || { echo "render_budget.sh: $scene has no box reference ($reference)" >&2; exit 1; }
source tools/benchmarks/provenance.sh
source tools/benchmarks/box_averaged.sh
provenance_start
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT

rows=()
for budget in "$@"; do
    for most in ${SAMPLES:-1 16}; do
        # The choice: its line names the settings (as options) and the time measured for them.
        line=$("$vk" render "scenes/$scene.json" --width "$width" --height "$height" --spp "$most" \
            --budget-ms "$budget" --out "$out/chosen.exr" 2>/dev/null |
            grep "^budget ")
        chosen=$(sed -n 's/^budget [^:]*: chose \(.*\) (measured \([0-9.]*\) ms.*/\1/p' <<<"$line")
        measured=$(sed -n 's/^budget [^:]*: chose .* (measured \([0-9.]*\) ms.*/\1/p' <<<"$line")
        [ -n "$measured" ] || { echo "render_budget.sh: no choice in: $line" >&2; exit 1; }
        error=$(box_averaged_image_relmse "$vk" "$out/chosen.exr" "$reference" "$out")
        rows+=("| $budget | $most | $chosen | $measured | $error |")
    done
done
echo "*$(provenance_line "$vk" "$scene at ${size}, relMSE of the image box-averaged to 400x300 against $reference")*"
echo
echo "| budget, ms | most samples per pixel | chose | measured, ms | relMSE |"
echo "| --- | --- | --- | --- | --- |"
printf '%s\n' "${rows[@]}"
