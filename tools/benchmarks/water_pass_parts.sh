#!/usr/bin/env bash
# water_pass_parts.sh [ROUNDS] [SCENE]
#
# Where the water pass's time goes: the scene (default pool) at 800x600, rendered by this tree's
# build with shader-only variants of the water's fragment shader, interleaved, the median of ROUNDS
# (default 3) rounds of the water pass and of the calibration pass (passes/common/calibration.hpp):
#   as built       shaders/ unchanged;
#   no refinement  the exact surface not looked for (water/surface_refinement.glsl returns at once:
#                  the mesh's point and normal are shaded);
#   no water path  the refracted ray's radiance (floor, caustic lookup, medium) a constant;
#   constant       the fragment shader writes the mesh's normal and nothing else: what is left is
#                  the mesh's vertices, its triangles' setup and rasterisation.
# The variants change the picture; only their times are read. Prints a Markdown table
# (docs/performance-log.md, "Where the water pass's time goes").
set -euo pipefail
cd "$(dirname "$0")/../.."
source "$(dirname "$0")/provenance.sh"
provenance_start
rounds=${1:-3} scene=${2:-pool}
source "$(dirname "$0")/water_shader_variant.sh"

water_variant as_built ""
water_variant no_refinement "
replace('water/surface_refinement.glsl', '    if (params.refine_steps == 0u) return false;', '    return false;')"
water_variant no_water_path "
replace('water/water_surface.frag',
        'transmitted = radiance_in_water(p, refracted_direction, false, f.T, refracted_length, caustic) / (n * n);',
        'transmitted = vec3(0.3) * refracted_direction.y;')"
water_variant constant "
text = open(root + '/water/water_surface.frag').read()
main = text.index('void main() {')
open(root + '/water/water_surface.frag', 'w').write(text[:main] + '''void main() {
    out_radiance = vec4(in_normal * 0.5 + 0.5, 1.0);
#ifdef VKWATER_CAUSTIC_LAYER
    out_caustic = vec4(0.0);
#endif
}
''')"

variants=(as_built no_refinement no_water_path constant)
for round in $(seq "$rounds"); do
  for name in "${variants[@]}"; do
    VKWATER_SHADER_DIR="$work/$name" "$vkwater" render "scenes/$scene.json" --width 800 --height 600 --repeat 2 \
      --out "$work/image.exr" 2>&1 | awk -v n="$name" '$1 == "water" && $3 == "ms" { print n, "water", $2 }
                                                      $1 == "calibration" { print n, "calibration", $2 }'
  done
done > "$work/times"

provenance_line "$vkwater"
echo "| $scene, 800x600 | water pass, ms | calibration, ms | water / calibration | water / as built |"
echo "| --- | --- | --- | --- | --- |"
python3 - "$work/times" "${variants[@]}" <<'PY'
import statistics, sys
rows = [line.split() for line in open(sys.argv[1])]
def median(name, part):
    return statistics.median(float(t) for n, p, t in rows if n == name and p == part)
base = median("as_built", "water")
for name in sys.argv[2:]:
    water, cal = median(name, "water"), median(name, "calibration")
    print(f"| {name.replace('_', ' ')} | {water:.1f} | {cal:.2f} | {water / cal:.0f} | {water / base:.2f} |")
PY
