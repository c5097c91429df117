#!/usr/bin/env bash
# convergence.sh SCENE BOX_REFERENCE [VKWATER]
#
# The real-time renderer's convergence against a box-filtered reference (tests/references/box/):
# image and caustic-layer relMSE against the samples per pixel (1, 4, 16, 64 at the scene's
# settings) and against the photons (sub_photons 1, 2, 4: 1, 4 and 16 photons per water cell,
# at 4 samples per pixel, with the map at map_scale 1 and at 4 texels per cell side), 400x300. For each series it prints the log-log
# slope between neighbouring points and the least-squares slope over the points; where the error
# stops halving, the last value is the series' floor (the part the knob does not remove). Prints
# Markdown (docs/accuracy.md keeps the tables). Minutes on 2 cores per scene.
source "$(dirname "$0")/scene_against_reference.sh"
source "$(dirname "$0")/provenance.sh"
provenance_start

# render N ARGS...: prints "relMSE causticRelMSE" of one render against the reference.
measure() {
  local line
  line=$("$vkwater" render "$scene" --width 400 --height 300 --out "$out/x.exr" --reference "$reference" "$@" 2>&1 |
    grep -E '^error against')
  echo "$(sed -n 's/.*: relMSE \([0-9.e+-]*\),.*/\1/p' <<<"$line") $(sed -n 's/.*caustic relMSE \([0-9.e+-]*\),.*/\1/p' <<<"$line")"
}

# series NAME "VALUE ARGS" ...: a table row per setting, then the slopes.
series() {
  local name=$1
  shift
  echo "| $name | relMSE | caustic relMSE | slope (relMSE) | slope (caustic) |"
  echo "| --- | --- | --- | --- | --- |"
  local previous_n="" previous_e="" previous_c="" points=""
  for setting in "$@"; do
    read -r n args <<<"$setting"
    read -r e c <<<"$(measure $args)"
    local se="" sc=""
    if [ -n "$previous_n" ]; then
      se=$(awk -v a="$previous_e" -v b="$e" -v m="$previous_n" -v n="$n" 'BEGIN{printf "%.2f", log(b/a)/log(n/m)}')
      sc=$(awk -v a="$previous_c" -v b="$c" -v m="$previous_n" -v n="$n" 'BEGIN{printf "%.2f", log(b/a)/log(n/m)}')
    fi
    echo "| $n | $e | $c | $se | $sc |"
    points="$points $n $e $c"
    previous_n=$n previous_e=$e previous_c=$c
  done
  awk -v p="$points" 'BEGIN{
    k = split(p, v, " "); m = k / 3;
    for (col = 2; col <= 3; ++col) {
      sx = sy = sxx = sxy = 0;
      for (i = 0; i < m; ++i) { x = log(v[3*i+1]); y = log(v[3*i+col]); sx += x; sy += y; sxx += x*x; sxy += x*y }
      slope[col] = (m * sxy - sx * sy) / (m * sxx - sx * sx);
    }
    printf "\nLeast-squares log-log slope: relMSE %.2f, caustic relMSE %.2f (relMSE falls as N^slope; -1 is\n", slope[2], slope[3];
    printf "the Monte Carlo rate of an unbiased estimate, 0 a floor).\n\n"
  }'
}

series "samples per pixel" "1 --spp 1" "4 --spp 4" "16 --spp 16" "64 --spp 64"
for scale in 1 4; do
  map="--spp 4 --set effects.caustics.map_scale=$scale"
  series "photons per water cell (map_scale $scale, 4 spp)" "1 $map --set effects.caustics.sub_photons=1" \
    "4 $map --set effects.caustics.sub_photons=2" "16 $map --set effects.caustics.sub_photons=4"
done
provenance_line "$vkwater"
