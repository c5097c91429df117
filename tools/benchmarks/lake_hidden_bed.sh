#!/usr/bin/env bash
# lake_hidden_bed.sh
#
# Lake's bed that the floating rock and the post hide from the camera, with the refraction view's
# second layer (effects.refraction_second_layer, passes/scene_views/scene_view.hpp) off and at its
# default (on in lake). Without it the water's lookup reads only what the camera sees, and the view
# rays refracted behind the rock and the post's foot reach bed that the camera cannot see straight
# on. Two rectangles of the 400x300 image hold those patches, found by eye in the per-pixel error
# and checked by rendering the scene without the rock (the patch behind it goes) and with the sun
# overhead (the patch stays where it is, so it is no shadow): behind the rock, 80x40 pixels at
# (280, 90), and around the post's foot, 60x35 at (165, 110). Lake is rendered at its defaults and
# at the best setting the sweeps found (16 samples per pixel, map_scale 2), each with the layer off
# and on, and compared against the box reference: the image's relMSE and HDR-FLIP, the caustic
# layer's relMSE over every pixel and over every pixel but the two rectangles (`vkwater compare
# --mask`). Prints a Markdown table (docs/accuracy.md, "The bed the rock and the post hide").
# Errors only: the machine's load does not change them.
set -euo pipefail
cd "$(dirname "$0")/../.."
source "$(dirname "$0")/provenance.sh"
provenance_start
vkwater=build/tools/vkwater/vkwater
[ -x "$vkwater" ] || { echo "build first: $vkwater is missing" >&2; exit 1; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
reference=tests/references/box/lake.exr

oiiotool --pattern constant:color=1,1,1 400x300 3 --fill:color=0,0,0 80x40+280+90 --fill:color=0,0,0 60x35+165+110 \
  -d float -o "$work/mask.exr"
metric() {  # NAME IMAGE [--layer caustic] [--mask MASK]
  local name=$1 image=$2
  shift 2
  "$vkwater" compare "$image" "$reference" "$@" | sed -n "s/^$name \([0-9.e-]*\).*/\1/p" | head -1
}

provenance_line "$vkwater" "errors only"
echo "| lake, 400x300 | second layer | relMSE | HDR-FLIP | caustic relMSE, every pixel | without the two rectangles (4.5% of the pixels) | share of the caustic error in them |"
echo "| --- | --- | --- | --- | --- | --- | --- |"
for setting in "defaults|" "16 samples, map_scale 2|--spp 16 --set effects.caustics.map_scale=2"; do
  IFS='|' read -r label options <<< "$setting"
  read -r -a args <<< "$options"
  for layer in off auto; do
    "$vkwater" render scenes/lake.json --width 400 --height 300 "${args[@]}" \
      --set effects.refraction_second_layer.mode=$layer --out "$work/lake.exr" > /dev/null 2>&1
    rel=$(metric relMSE "$work/lake.exr")
    flip=$(metric FLIP "$work/lake.exr")
    all=$(metric relMSE "$work/lake.exr" --layer caustic)
    masked=$(metric relMSE "$work/lake.exr" --layer caustic --mask "$work/mask.exr")
    python3 -c "rel, flip, all, masked = $rel, $flip, $all, $masked
print(f'| $label | ${layer/auto/on} | {rel:.5f} | {flip:.4f} | {all:.4f} | {masked:.4f} | {1 - masked / all:.0%} |')"
  done
done
