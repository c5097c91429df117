#!/usr/bin/env bash
# scene_hit_filter.sh [ROUNDS] [SCENE ...]
#
# What reading a scene lookup's hit between the view's texels buys and costs
# (shaders/water/scene_lookup.glsl, filter_hit). Three shader-only builds of the water's fragment
# shader:
#   nearest    the hit's radiance and caustic layer from the one texel its lookup ended on (filter_hit
#              returns at once: the shader before the filter, bit for bit);
#   as built   shaders/ unchanged: read bilinearly where the ray's point at the hit projects, over
#              the texels around it that show the same surface;
#   stepped    one more fixed-point step on that bilinear surface first, then read where the ray's
#              point at the stepped distance projects (not kept).
# First the error of each at 400x300 against the scene's committed references (whole image, HDR-FLIP
# and caustic layer; the box-filtered one where there is one, and the point-sampled one); then the
# water pass at 800x600, interleaved, the median of ROUNDS (default 3) rounds, in calibration
# passes of the same frame. SCENE: names under scenes/ with scene views (default lake box
# showcase/shore showcase/lagoon). Prints two Markdown tables (docs/accuracy.md, "Hits read between
# the view's texels").
set -euo pipefail
cd "$(dirname "$0")/../.."
source "$(dirname "$0")/provenance.sh"
provenance_start
rounds=${1:-3}
shift || true
scenes=("$@")
[ ${#scenes[@]} -gt 0 ] || scenes=(lake box showcase/shore showcase/lagoon)
source "$(dirname "$0")/water_shader_variant.sh"
water_variant nearest "
replace('water/scene_lookup.glsl',
        'void filter_hit(sampler2D view, bool mirrored, vec3 p, vec3 d, inout SceneHit hit) {',
        'void filter_hit(sampler2D view, bool mirrored, vec3 p, vec3 d, inout SceneHit hit) {\n    return;')"
water_variant as_built ""
water_variant stepped "
replace('water/scene_lookup.glsl', '    hit.radiance = value.rgb;\n    hit.texel_base = base;',
        open('tools/benchmarks/scene_hit_step.glsl').read() + '    hit.radiance = value.rgb;\n    hit.texel_base = base;')"
variants=(nearest as_built stepped)

# The committed references of a scene: the box-filtered one first where there is one.
references_of() {
  local name=$1 dir=tests/references
  case $name in showcase/*) dir=tests/references/showcase; name=${name#showcase/} ;; esac
  [ -f "tests/references/box/$name.exr" ] && [ "$dir" = tests/references ] && echo "tests/references/box/$name.exr"
  [ -f "$dir/$name.exr" ] && echo "$dir/$name.exr"
  return 0
}

provenance_line "$vkwater" "errors only"
echo "| scene, 400x300 | reference | relMSE: nearest, as built, stepped | HDR-FLIP: nearest, as built, stepped | caustic relMSE: nearest, as built, stepped |"
echo "| --- | --- | --- | --- | --- |"
for scene in "${scenes[@]}"; do
  for reference in $(references_of "$scene"); do
    for name in "${variants[@]}"; do
      VKWATER_SHADER_DIR="$work/$name" "$vkwater" render "scenes/$scene.json" --width 400 --height 300 \
        --reference "$reference" --out "$work/image.exr" 2>&1 |
        sed -n 's/.*: relMSE \([0-9.e-]*\), FLIP \([0-9.e-]*\),.*caustic relMSE \([0-9.e-]*\),.*/\1 \2 \3/p' \
          > "$work/error_$name"
      [ -s "$work/error_$name" ] || { echo "scene_hit_filter.sh: no error line for $scene ($name)" >&2; exit 1; }
    done
    python3 - "$scene" "$reference" "$work" "${variants[@]}" <<'PY'
import sys
scene, reference, work, names = sys.argv[1], sys.argv[2], sys.argv[3], sys.argv[4:]
errors = [open(f"{work}/error_{n}").read().split() for n in names]
cells = [", ".join(e[k] for e in errors) for k in range(3)]
print(f"| {scene} | `{reference}` | " + " | ".join(cells) + " |")
PY
  done
done
echo

for round in $(seq "$rounds"); do
  for scene in "${scenes[@]}"; do
    for name in "${variants[@]}"; do
      VKWATER_SHADER_DIR="$work/$name" "$vkwater" render "scenes/$scene.json" --width 800 --height 600 --repeat 2 \
        --out "$work/image.exr" 2>&1 | awk -v s="$scene $name" '$1 == "water" && $3 == "ms" { print s, "water", $2 }
                                                               $1 == "calibration" { print s, "calibration", $2 }'
    done
  done
done > "$work/times"

provenance_line "$vkwater" "$rounds interleaved rounds"
echo "| scene, 800x600 | water pass, ms: nearest, as built, stepped | water / calibration: nearest, as built, stepped | as built / nearest |"
echo "| --- | --- | --- | --- |"
python3 - "$work/times" "${variants[@]}" -- "${scenes[@]}" <<'PY'
import statistics, sys
args = sys.argv[2:]
names, scenes = args[:args.index("--")], args[args.index("--") + 1:]
rows = [line.split() for line in open(sys.argv[1])]
def median(scene, name, part):
    return statistics.median(float(r[3]) for r in rows if r[:3] == [scene, name, part])
for scene in scenes:
    water = [median(scene, n, "water") for n in names]
    cal = [water[i] / median(scene, n, "calibration") for i, n in enumerate(names)]
    print(f"| {scene} | " + ", ".join(f"{w:.1f}" for w in water) + " | " + ", ".join(f"{c:.0f}" for c in cal) +
          f" | {water[1] / water[0]:.2f} |")
PY
