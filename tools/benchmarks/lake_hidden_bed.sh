#!/usr/bin/env bash
# lake_hidden_bed.sh
#
# How much of lake's caustic-layer error lies where the refracted view rays reach lake bed that the
# floating rock and the post hide from the camera (the refraction view, which the water's projective
# lookup reads, holds only what the camera sees: docs/techniques/reflection_refraction.md). Two
# rectangles of the 400x300 image, found by eye in the per-pixel error and checked by rendering
# the scene without the rock (the patch behind it goes) and with the sun overhead (the patch stays
# where it is, so it is no shadow): behind the rock, 80x40 pixels at (280, 90), and around the
# post's foot, 60x35 at (165, 110). Lake is rendered at its defaults and at the best setting the
# sweeps found (16 samples per pixel, map_scale 2); each is compared against the box reference's
# caustic layer over every pixel and over every pixel but the two rectangles (`vkwater compare
# --mask`). Prints a Markdown table (docs/accuracy.md, "Lake's hidden bed"). Errors only: the
# machine's load does not change them.
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
caustic_relmse() {  # IMAGE [MASK]
  "$vkwater" compare "$1" "$reference" --layer caustic ${2:+--mask "$2"} | sed -n 's/.*relMSE \([0-9.e-]*\).*/\1/p' | head -1
}

provenance_line "$vkwater" "errors only"
echo "| lake, 400x300 | caustic relMSE, every pixel | without the two rectangles (4.5% of the pixels) | share of the error in them |"
echo "| --- | --- | --- | --- |"
for setting in "defaults|" "16 samples, map_scale 2|--spp 16 --set effects.caustics.map_scale=2"; do
  IFS='|' read -r label options <<< "$setting"
  read -r -a args <<< "$options"
  "$vkwater" render scenes/lake.json --width 400 --height 300 "${args[@]}" --out "$work/lake.exr" > /dev/null 2>&1
  all=$(caustic_relmse "$work/lake.exr")
  masked=$(caustic_relmse "$work/lake.exr" "$work/mask.exr")
  python3 -c "all, masked = $all, $masked
print(f'| $label | {all:.4f} | {masked:.4f} | {1 - masked / all:.0%} |')"
done
