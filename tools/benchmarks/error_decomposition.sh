#!/usr/bin/env bash
# error_decomposition.sh SCENE BOX_REFERENCE [VKWATER]
#
# Where a scene's error against a box-filtered reference comes from: the real-time renderer at
# 1 and 16 samples per pixel, caustic map_scale 1, 2 and 4, the adaptive and footprint kernels
# (the footprint kernel at map_scale 4 with 1 sample only: 16 of its frames take about 20 min
# on 2 cores), 400x300, each setting's image and caustic-layer relMSE and its frame time (the
# sum of its sub-frames). BOX_REFERENCE: `vkwater reference SCENE --width 400 --height 300 --spp 16`.
# Prints a Markdown table (docs/accuracy.md keeps one per scene). The times are one frame each
# on a shared machine: read them as rough.
source "$(dirname "$0")/scene_against_reference.sh"
source "$(dirname "$0")/provenance.sh"
provenance_start
echo "| kernel | map_scale | spp | relMSE | caustic relMSE | frame ms |"
echo "| --- | --- | --- | --- | --- | --- |"
settings=("adaptive 1 1" "adaptive 1 16" "adaptive 2 1" "adaptive 2 16" "adaptive 4 1" "adaptive 4 16"
  "footprint 1 1" "footprint 1 16" "footprint 2 1" "footprint 2 16" "footprint 4 1")
for setting in "${settings[@]}"; do
  read -r kernel scale spp <<<"$setting"
  line=$("$vkwater" render "$scene" --width 400 --height 300 --spp "$spp" --out "$out/x.exr" \
    --reference "$reference" --set effects.caustics.kernel=$kernel \
    --set effects.caustics.map_scale=$scale 2>&1 | grep -E '^(time|error against)')
  ms=$(sed -n 's/^time: \([0-9.]*\) ms.*/\1/p' <<<"$line")
  rel=$(sed -n 's/.*: relMSE \([0-9.e+-]*\),.*/\1/p' <<<"$line")
  caustic=$(sed -n 's/.*caustic relMSE \([0-9.e+-]*\),.*/\1/p' <<<"$line")
  echo "| $kernel | $scale | $spp | $rel | $caustic | $ms |"
done
provenance_line "$vkwater"
