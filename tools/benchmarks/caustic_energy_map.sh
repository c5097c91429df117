#!/usr/bin/env bash
# tools/benchmarks/caustic_energy_map.sh IMAGE REFERENCE [BLOCKS_X BLOCKS_Y]: where a render's caustic
# layer gains or loses energy against its reference. Prints the ratio of the two layers' sums
# (caustic.G) over the whole image and over a grid of blocks (default 10 x 10; '.' where the
# reference's block holds under 1e-5 of its total), then the share of the reference's caustic
# energy that lies in pixels where the render's layer is exactly 0 (what a lookup that found no
# receiver leaves). Needs oiiotool.
#
#   vkwater render scenes/lake.json --width 400 --height 300 --out lake.exr
#   tools/benchmarks/caustic_energy_map.sh lake.exr tests/references/box/lake.exr
set -euo pipefail
image=$1 reference=$2 blocks_x=${3:-10} blocks_y=${4:-10}
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
for name in image reference; do
    oiiotool "${!name}" --ch caustic.G -o "$scratch/$name.exr"
    oiiotool --dumpdata "$scratch/$name.exr" >"$scratch/$name.txt"
done
python3 - "$scratch/image.txt" "$scratch/reference.txt" "$blocks_x" "$blocks_y" <<'PY'
import re, sys
def load(path):
    pixels = {}
    for line in open(path):
        m = re.match(r"\s*Pixel \((\d+), (\d+)\): (\S+)", line)
        if m:
            pixels[(int(m.group(1)), int(m.group(2)))] = float(m.group(3))
    return pixels
image, reference = load(sys.argv[1]), load(sys.argv[2])
if image.keys() != reference.keys():
    sys.exit("caustic_energy_map.sh: the two images differ in size")
bx, by = int(sys.argv[3]), int(sys.argv[4])
width = max(x for x, _ in reference) + 1
height = max(y for _, y in reference) + 1
total_image, total_reference = sum(image.values()), sum(reference.values())
print(f"caustic.G sums: image {total_image:.6g}, reference {total_reference:.6g}, ratio {total_image / total_reference:.4f}")
print(f"ratio per block ({bx} x {by} blocks, rows from the top):")
for j in range(by):
    row = []
    for i in range(bx):
        keys = [(x, y) for x in range(i * width // bx, (i + 1) * width // bx)
                for y in range(j * height // by, (j + 1) * height // by)]
        a, b = sum(image[k] for k in keys), sum(reference[k] for k in keys)
        row.append(f"{a / b:6.3f}" if b > 1e-5 * total_reference else "     .")
    print(" ".join(row))
lost = sum(reference[k] for k in reference if image[k] == 0.0)
print(f"share of the reference's caustic energy where the image's layer is 0: {lost / total_reference:.4f}")
PY
