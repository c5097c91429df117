#!/usr/bin/env bash
# declare_ratio.sh OLD_COMMIT [ROUNDS] [SCENE ...]
#
# The frame's CPU share, `vkwater render`'s "declare + compile graph" line (the needs' decision,
# the graph's declaration and its compilation, timed inside the renderer between lavapipe's
# frames), of this tree's build against OLD_COMMIT's built beside it (old_build.sh), interleaved:
# each round runs both builds once per scene, which one goes first alternating, and each figure is
# the median over the rounds. The line times the last frame of REPEAT (default 4), so that the
# frame before it ran the same graph. WIDTH and HEIGHT default to 800x600; scenes default to pool,
# lake and ocean. Prints a Markdown table and where it comes from.
#
#   tools/benchmarks/declare_ratio.sh c0f44c7 7 pool
set -euo pipefail
USAGE=tools/benchmarks/declare_ratio.sh
source "$(dirname "$0")/old_build.sh"
source "$root/tools/benchmarks/provenance.sh"
source "$root/tools/benchmarks/median.sh"
provenance_start
[ ${#scenes[@]} -gt 0 ] || scenes=(pool lake ocean)
width=${WIDTH:-800} height=${HEIGHT:-600} repeat=${REPEAT:-4}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

declare_ms() {
  "$1" render "scenes/$2.json" --width "$width" --height "$height" --repeat "$repeat" --out "$work/frame.exr" \
    2> /dev/null | sed -n 's/^ *declare + compile graph *\([0-9.]*\) ms.*/\1/p'
}

for round in $(seq 1 "$rounds"); do
  for scene in "${scenes[@]}"; do
    if [ $((round % 2)) -eq 1 ]; then order=(old new); else order=(new old); fi
    for build in "${order[@]}"; do
      if [ "$build" = old ]; then vk=$old_vk; else vk=$new_vk; fi
      echo "$scene $build $(declare_ms "$vk" "$scene")"
    done
  done
done > "$work/times.txt"

echo "| scene | $old_commit, ms | this tree, ms | this tree / $old_commit |"
echo "| --- | --- | --- | --- |"
for scene in "${scenes[@]}"; do
  old=$(awk -v s="$scene" '$1 == s && $2 == "old" { print $3 }' "$work/times.txt" | median)
  new=$(awk -v s="$scene" '$1 == s && $2 == "new" { print $3 }' "$work/times.txt" | median)
  awk -v s="$scene" -v o="$old" -v n="$new" 'BEGIN { printf "| %s | %.3f | %.3f | %.2f |\n", s, o, n, n / o }'
done
provenance_line "$new_vk" "${width}x$height, frame $repeat of $repeat, medians of $rounds interleaved rounds; the old build: $old_commit"
