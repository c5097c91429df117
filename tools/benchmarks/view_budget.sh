#!/usr/bin/env bash
# tools/benchmarks/view_budget.sh [BUDGET_MS] [FRAMES] [WxH] [SCENE...]: the viewer under a
# frame-time budget (default 66 ms, lavapipe's default; 200 frames; 800x600; every built-in scene,
# the showcase ones too). For each scene: `vkwater view --budget-ms` under xvfb-run, its median
# frame interval (the viewer's summary, warm-up and timing frames left out), the settings it ended
# at and how many changes it made; then, for the scenes with a box-filtered reference
# (tests/references/box/, 400x300), the relMSE of the scene's own settings and of the budget's
# settings, each rendered at WxH and box-averaged down to 400x300 (oiiotool --resize:filter=box):
# a WxH image averaged over 400x300 pixels estimates the same pixel integral as the reference.
# Prints one Markdown table row per scene (docs/performance.md "The frame-time budget").
set -euo pipefail
cd "$(dirname "$0")/../.."
source "$(dirname "$0")/provenance.sh"
source "$(dirname "$0")/box_averaged.sh"
provenance_start
budget=${1:-66}
frames=${2:-200}
size=${3:-800x600}
shift $(($# < 3 ? $# : 3))
scenes=("$@")
[ ${#scenes[@]} -gt 0 ] || scenes=(pool lake ocean calm underwater box showcase/pool showcase/lagoon)
width=${size%x*}
height=${size#*x}
vk=${VKWATER:-build/tools/vkwater/vkwater}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT

relmse_at_reference_size() {  # SCENE ARGS...: relMSE against the box reference, or "-"
    local scene=$1
    shift
    local reference="tests/references/box/$scene.exr"
    [ -f "$reference" ] || { echo "-"; return; }
    box_averaged_relmse "$vk" "scenes/$scene.json" "$reference" "$width" "$height" "$out" "$@"
}

provenance_line "$vk"
echo "| scene | median frame ms | fps | changes | settings at exit | relMSE own settings | relMSE budget's settings |"
echo "| --- | --- | --- | --- | --- | --- | --- |"
for scene in "${scenes[@]}"; do
    log="$out/view.log"
    xvfb-run -a "$vk" view "scenes/$scene.json" --width "$width" --height "$height" --frames "$frames" \
        --budget-ms "$budget" >"$log" 2>&1
    median=$(awk '/^frames:/ {for (i = 1; i <= NF; ++i) if ($i == "median") {print $(i + 1); exit}}' "$log")
    fps=$(python3 -c "print(f'{1000 / $median:.1f}')")
    settings=$(sed -n 's/.*settings at exit: \(.*\) (\([0-9]*\) changes)$/\1/p' "$log")
    changes=$(sed -n 's/.*settings at exit: .* (\([0-9]*\) changes)$/\1/p' "$log")
    # Split as a shell would: a --set value with brackets comes quoted ("receivers[0].resolution").
    args=()
    if [ "$settings" != "the scene's own settings" ]; then
        mapfile -t args < <(python3 -c 'import shlex, sys; print("\n".join(shlex.split(sys.argv[1])))' "$settings")
    fi
    own=$(relmse_at_reference_size "$scene")
    chosen=$(relmse_at_reference_size "$scene" "${args[@]}")
    echo "| $scene | $median | $fps | $changes | \`$settings\` | $own | $chosen |"
done
