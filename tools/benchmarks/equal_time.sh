#!/usr/bin/env bash
# equal_time.sh OLD_COMMIT [ROUNDS] [SCENE ...]
#
# The error at equal frame time: OLD_COMMIT's defaults against this tree's settings of samples per
# pixel and caustic map resolution, each with the scene's other settings and with the godrays off
# and a 128^2 water mesh ("light"), each scene's image and caustic-layer relMSE against its
# box-filtered reference (tests/references/box/SCENE.exr), 400x300. Each round renders the old
# build's default frame and then every setting of this tree (each render --repeat 2, the last
# frame timed, the sum of its sub-frames); a setting's time is the median over the rounds of its
# time over the same round's old frame, so the shared machine's swings cancel. The errors do not
# depend on the round. Each round also asks this tree's budget for the old frame's time
# (`render --spp 16 --budget-ms <that round's old frame>`), which turns every knob it has (photon
# grid, map, kernel, godrays, mesh, resolution scale and samples per pixel): its choice, its
# measured time over the old frame and its errors, a row per round. Prints per scene a Markdown
# table and the best setting whose time ratio is at most 1 (docs/accuracy.md keeps them). OLD_BUILD=DIR uses an existing build of OLD_COMMIT
# instead of building one in build/frame_ratio/OLD_COMMIT (as frame_ratio.sh does).
USAGE=tools/benchmarks/equal_time.sh
source "$(dirname "$0")/old_build.sh"
source "$(dirname "$0")/provenance.sh"
provenance_start
[ ${#scenes[@]} -gt 0 ] || scenes=(pool lake ocean)
# spp, effects.caustics.map_scale, and the rest: the scene's own ("own"), or "light": the godrays
# off and a 128^2 water mesh, what the budget turns first (their error is small where the samples'
# time goes further).
settings=()
for rest in own light; do
  for setting in "1 1" "4 1" "9 1" "16 1" "1 2" "4 2" "9 2" "16 2"; do settings+=("$setting $rest"); done
done
rest_args() { [ "$1" = light ] && echo "--set effects.godrays.mode=off --set water.mesh_resolution=128"; true; }
rest_name() { [ "$1" = light ] && echo "godrays off, mesh 128" || echo "the scene's own"; }

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# frame_ms VKWATER OUT ARGS...: renders and prints the timed frame's milliseconds (its pass list's
# `frame` line, which builds before the `time:` line have too).
frame_ms() {
  local vk=$1 out=$2
  shift 2
  "$vk" render --width 400 --height 300 --repeat 2 --out "$out" "$@" 2> /dev/null |
    sed -n 's/^  frame  *\([0-9.]*\) ms.*/\1/p'
}

# errors EXR REFERENCE: "relMSE causticRelMSE" by this tree's compare.
errors() {
  local text
  text=$("$new_vk" compare "$1" "$2")
  echo "$(sed -n 's/^relMSE \([0-9.e+-]*\).*/\1/p' <<<"$text") $(sed -n 's/^caustic relMSE \([0-9.e+-]*\).*/\1/p' <<<"$text")"
}

for scene in "${scenes[@]}"; do
  reference=tests/references/box/$scene.exr
  for round in $(seq 1 "$rounds"); do
    old_ms=$(frame_ms "$old_vk" "$work/old.exr" "scenes/$scene.json") || true
    if [ -z "$old_ms" ]; then
      # e.g. a scene file written for a feature the old build lacks
      echo "equal_time.sh: $old_commit does not render scenes/$scene.json:" >&2
      "$old_vk" render --width 16 --height 12 --out "$work/old.exr" "scenes/$scene.json" 2>&1 | tail -1 >&2 || true
      exit 1
    fi
    for setting in "${settings[@]}"; do
      read -r spp scale rest <<<"$setting"
      read -r -a extra <<<"$(rest_args "$rest")"
      ms=$(frame_ms "$new_vk" "$work/new-$spp-$scale-$rest.exr" "scenes/$scene.json" --spp "$spp" \
        --set effects.caustics.map_scale="$scale" "${extra[@]}") || true
      [ -n "$ms" ] || { echo "equal_time.sh: $scene at --spp $spp, map_scale $scale, $rest: no frame time" >&2; exit 1; }
      echo "$spp $scale $(awk -v a="$ms" -v b="$old_ms" 'BEGIN { printf "%.4f", a / b }') $ms $old_ms $rest"
    done
    # The budget's own choice for the old frame's time: its line names the settings and the time
    # it measured for them.
    line=$("$new_vk" render "scenes/$scene.json" --width 400 --height 300 --spp 16 --budget-ms "$old_ms" \
      --out "$work/budget-$round.exr" 2> "$work/budget.err" | grep "^budget " || true)
    chosen=$(sed -n 's/^budget [^:]*: chose \(.*\) (measured \([0-9.]*\) ms.*/\1/p' <<<"$line")
    measured=$(sed -n 's/^budget [^:]*: chose .* (measured \([0-9.]*\) ms.*/\1/p' <<<"$line")
    if [ -z "$measured" ]; then
      echo "equal_time.sh: $scene: no budget choice at $old_ms ms in: $line" >&2
      tail -3 "$work/budget.err" >&2
      exit 1
    fi
    echo "$round|$chosen|$(awk -v a="$measured" -v b="$old_ms" 'BEGIN { printf "%.4f", a / b }')" >> "$work/budget.txt"
  done > "$work/times.txt"
  read -r old_rel old_caustic <<<"$(errors "$work/old.exr" "$reference")"
  old_median=$(awk '{ print $5 }' "$work/times.txt" | sort -g | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }')
  echo "### $scene"
  echo
  echo "$old_commit's defaults: relMSE $old_rel, caustic relMSE $old_caustic, frame $old_median ms (median)."
  echo
  echo "| spp | map_scale | the rest | frame / $old_commit's frame | relMSE | / $old_commit's | caustic relMSE | / $old_commit's |"
  echo "| --- | --- | --- | --- | --- | --- | --- | --- |"
  best=""
  for setting in "${settings[@]}"; do
    read -r spp scale rest <<<"$setting"
    ratio=$(awk -v s="$spp" -v m="$scale" -v r="$rest" '$1 == s && $2 == m && $6 == r { print $3 }' "$work/times.txt" |
      sort -g | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }')
    read -r rel caustic <<<"$(errors "$work/new-$spp-$scale-$rest.exr" "$reference")"
    rel_ratio=$(awk -v a="$rel" -v b="$old_rel" 'BEGIN { printf "%.2f", a / b }')
    caustic_ratio=$(awk -v a="$caustic" -v b="$old_caustic" 'BEGIN { printf "%.2f", a / b }')
    echo "| $spp | $scale | $(rest_name "$rest") | $ratio | $rel | $rel_ratio | $caustic | $caustic_ratio |"
    if awk -v r="$ratio" 'BEGIN { exit !(r <= 1) }'; then
      if [ -z "$best" ] || awk -v a="$rel" -v b="${best##* }" 'BEGIN { exit !(a < b) }'; then
        best="spp $spp, map_scale $scale, $(rest_name "$rest"): relMSE x$rel_ratio, caustic relMSE x$caustic_ratio $rel"
      fi
    fi
  done
  echo
  if [ -n "$best" ]; then
    echo "Lowest relMSE within $old_commit's frame time: ${best% *}."
  else
    echo "No setting within $old_commit's frame time."
  fi
  echo
  echo "The budget at $old_commit's frame time (\`--spp 16 --budget-ms\` that round's $old_commit frame):"
  echo
  echo "| round | chose | its measured frame / $old_commit's frame | relMSE | / $old_commit's | caustic relMSE | / $old_commit's |"
  echo "| --- | --- | --- | --- | --- | --- | --- |"
  while IFS='|' read -r round chosen ratio; do
    read -r rel caustic <<<"$(errors "$work/budget-$round.exr" "$reference")"
    echo "| $round | $chosen | $ratio | $rel | $(awk -v a="$rel" -v b="$old_rel" 'BEGIN { printf "%.2f", a / b }') |" \
      "$caustic | $(awk -v a="$caustic" -v b="$old_caustic" 'BEGIN { printf "%.2f", a / b }') |"
  done < "$work/budget.txt"
  rm -f "$work/budget.txt"
  echo
done
provenance_line "$new_vk" "the old build: $old_commit"
