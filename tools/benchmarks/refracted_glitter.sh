#!/usr/bin/env bash
# tools/benchmarks/refracted_glitter.sh [SPP]: the sun's glitter seen from the water, against the
# reference (docs/accuracy.md, "Sun glitter", "Seen from the water"). scenes/ocean.json in pure water
# (so that the sun's light is not lost in the coastal water's haze), the eye 25 m under the surface
# at x = 0, 7 and -11 m, looking up toward the refracted sun (46.4 degrees from the vertical), at
# 160x120: the real-time image with the glitter off (the sun's disk at the pixels' centres) and on
# (the transmission lobe), and the reference with SPP samples per pixel (default 16; about 3 min
# each on 2 cores). Per eye: the sun's light, the sum of the green radiance over the 60 x 55 pixels
# around its image less what the region holds without the sun (the glitter-off image's mean over the
# rest of the frame, times the region's pixels: the background is even there); the whole image's
# bias and the FLIP of 8x8-pixel block means, each against the reference. Prints the provenance line
# and a Markdown table.
set -euo pipefail
cd "$(dirname "$0")/../.."
spp=${1:-16}
vk=${VKWATER:-build/tools/vkwater/vkwater}
[ -x "$vk" ] || { echo "refracted_glitter: build this tree first ($vk)" >&2; exit 1; }
source tools/benchmarks/provenance.sh
provenance_start
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT

region=60x55+50+35  # oiiotool's WxH+X+Y: the pixels around the sun's image in every view
pixels=$((60 * 55))

# The green channel's sum over the region and its mean over the rest of the image.
green_sums() {  # EXR
    python3 - "$1" "$(oiiotool "$1" --ch G --cut "$region" --printstats 2>/dev/null | sed -n 's/.*Stats Avg: *\([^ ]*\).*/\1/p')" \
        "$(oiiotool "$1" --ch G --printstats 2>/dev/null | sed -n 's/.*Stats Avg: *\([^ ]*\).*/\1/p')" "$pixels" <<'EOF'
import sys
region_mean, whole_mean, pixels = float(sys.argv[2]), float(sys.argv[3]), int(sys.argv[4])
whole = whole_mean * 160 * 120
print(region_mean * pixels, (whole - region_mean * pixels) / (160 * 120 - pixels))
EOF
}

compare_field() {  # IMAGE REFERENCE FIELD: a figure of `vkwater compare --downsample 8`
    "$vk" compare "$1" "$2" --downsample 8 | sed -n "s/^$3 \([^ ]*\).*/\1/p" | head -1
}

echo "| --- | --- | --- | --- | --- | --- |" >"$out/rows"
for x in 0 7 -11; do
    view=(--set "camera.position=[$x,-25,20]" --set "camera.target=[$x,13.08,-20]" --set medium.preset=pure
        --width 160 --height 120)
    for glitter in false true; do
        "$vk" render scenes/ocean.json "${view[@]}" --set "effects.water.glitter=$glitter" --out "$out/$glitter.exr" -q
    done
    "$vk" reference scenes/ocean.json "${view[@]}" --spp "$spp" --out "$out/reference.exr" >/dev/null 2>&1
    read -r off_sum background < <(green_sums "$out/false.exr")
    read -r on_sum _ < <(green_sums "$out/true.exr")
    read -r reference_sum _ < <(green_sums "$out/reference.exr")
    # Without the sun the region holds its background, as elsewhere in the image.
    sky=$(python3 -c "print($background * $pixels)")
    row=$(python3 -c "
sky = $sky
print('| %s m | %.0f | %.0f | %.0f |' % ('$x', $off_sum - sky, $on_sum - sky, $reference_sum - sky))")
    bias_off=$(compare_field "$out/false.exr" "$out/reference.exr" bias)
    bias_on=$(compare_field "$out/true.exr" "$out/reference.exr" bias)
    flip_off=$(compare_field "$out/false.exr" "$out/reference.exr" "FLIP (8x box-downsampled to 20x15)")
    flip_on=$(compare_field "$out/true.exr" "$out/reference.exr" "FLIP (8x box-downsampled to 20x15)")
    python3 -c "print('$row %+.0f%% / %+.0f%% | %.3f / %.3f |' % (100 * $bias_off, 100 * $bias_on, $flip_off, $flip_on))" >>"$out/rows"
done
provenance_line "$vk" "the reference at $spp samples per pixel; errors only, which the machine's load does not change"
echo
echo "| eye x | sun's light: disk at pixel centres | lobe | reference | image bias: disk / lobe | FLIP, 8x blocks: disk / lobe |"
cat "$out/rows"
