#!/usr/bin/env bash
# frame_ratio.sh OLD_COMMIT [ROUNDS] [SCENE ...]
#
# The frame and every pass of the built-in scenes at 800x600, from this tree's build (build/)
# and from OLD_COMMIT built beside it, interleaved: each round runs every scene with both builds,
# alternating which goes first, and the table takes each figure's median over the rounds. Times
# are printed in units of the same frame's own passes, so the 2x swings of a shared machine
# cancel:
#   cal   the calibration pass (a constant shader over every pixel; passes/common/calibration.hpp),
#         recorded in every timed frame of builds that have it;
#   sky   the sky pass (a cheap full-screen pass every build has): the unit both builds share.
# Fence-timed on CPU devices, GPU timestamps elsewhere (vkwater render's own timing).
#
# OLD_BUILD=DIR uses an existing build of OLD_COMMIT instead of building one in
# build/frame_ratio/OLD_COMMIT. WIDTH and HEIGHT (default 800x600), REPEAT (frames per render,
# the last one timed; default 2) and RENDER_ARGS (more render options, e.g. "--spp 4") change what
# both builds render. Prints a Markdown table (docs/performance.md keeps one).
USAGE=tools/benchmarks/frame_ratio.sh
source "$(dirname "$0")/old_build.sh"
source "$(dirname "$0")/provenance.sh"
provenance_start
[ ${#scenes[@]} -gt 0 ] || scenes=(calm pool lake ocean underwater box)
width=${WIDTH:-800} height=${HEIGHT:-600} repeat=${REPEAT:-2}
read -r -a render_args <<< "${RENDER_ARGS:-}"

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# run BUILD_NAME VKWATER SCENE ROUND: one render's pass lines as "scene build round pass ms".
run() {
  local name=$1 vk=$2 scene=$3 round=$4
  # Each build reads its own shaders: a build's SPIR-V is where its binary was built.
  "$vk" render "scenes/$scene.json" --width $width --height $height --repeat "$repeat" "${render_args[@]}" --out "$work/$name.exr" 2> /dev/null |
    awk -v prefix="$scene\t$name\t$round" -v skip_declare=1 -f tools/benchmarks/pass_times.awk
}

for round in $(seq 1 "$rounds"); do
  for scene in "${scenes[@]}"; do
    if [ $((round % 2)) -eq 1 ]; then
      run old "$old_vk" "$scene" "$round"; run new "$new_vk" "$scene" "$round"
    else
      run new "$new_vk" "$scene" "$round"; run old "$old_vk" "$scene" "$round"
    fi
  done
done > "$work/times.tsv"

# Per round, each pass over that round's unit of the same frame; then the median over rounds.
awk -F'\t' -v old="$old_commit" '
  { key = $1 SUBSEP $2 SUBSEP $3; ms[key, $4] = $5; if ($4 == "calibration") cal[key] = $5; if ($4 == "sky") sky[key] = $5
    if (!(($1, $2, $4) in seen)) { seen[$1, $2, $4] = 1; order[$1, $2, ++count[$1, $2]] = $4 }
    rounds[$3] = 1; scenes[$1] = 1 }
  function median(values, n,    i, j, t) {
    for (i = 2; i <= n; i++) for (j = i; j > 1 && values[j - 1] > values[j]; j--) { t = values[j]; values[j] = values[j - 1]; values[j - 1] = t }
    return n % 2 ? values[(n + 1) / 2] : (values[n / 2] + values[n / 2 + 1]) / 2
  }
  function unit_median(scene, build, pass, units,    r, n, v, key) {
    n = 0; delete v
    for (r in rounds) { key = scene SUBSEP build SUBSEP r
      if (((key, pass) in ms) && (key in units) && units[key] > 0) v[++n] = ms[key, pass] / units[key] }
    return n ? sprintf("%.1f", median(v, n)) : "-"
  }
  function ms_median(scene, build, pass,    r, n, v, key) {
    n = 0; delete v
    for (r in rounds) { key = scene SUBSEP build SUBSEP r; if ((key, pass) in ms) v[++n] = ms[key, pass] }
    return n ? sprintf("%.1f", median(v, n)) : "-"
  }
  END {
    print "| scene | pass | " old " ms | " old " sky | new ms | new sky | new cal |"
    print "| --- | --- | --- | --- | --- | --- | --- |"
    for (scene in scenes) {
      delete listed
      for (i = 1; i <= count[scene, "new"]; i++) { p = order[scene, "new", i]; listed[p] = 1
        print "| " scene " | " p " | " ms_median(scene, "old", p) " | " unit_median(scene, "old", p, sky) " | " ms_median(scene, "new", p) " | " unit_median(scene, "new", p, sky) " | " unit_median(scene, "new", p, cal) " |" }
      for (i = 1; i <= count[scene, "old"]; i++) { p = order[scene, "old", i]; if (p in listed) continue
        print "| " scene " | " p " | " ms_median(scene, "old", p) " | " unit_median(scene, "old", p, sky) " | - | - | - |" }
    }
  }' "$work/times.tsv"
provenance_line "$new_vk" "the old build: $old_commit"
