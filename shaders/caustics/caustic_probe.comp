#version 460
// Test kernel (tests/caustics/): caustic_irradiance at a count_x x count_z lattice of receiver
// points, so the tests read the caustics exactly as a receiver shader will.
#extension GL_GOOGLE_include_directive : require

#define CAUSTIC_SET 0
#define CAUSTIC_PARAMS_BINDING 0
#define CAUSTIC_MAP_BINDING 1
#include "caustics/caustic_lookup.glsl"

layout(local_size_x = 64) in;

layout(set = 0, binding = 2, std430) writeonly buffer Probes { vec4 probes[]; };

layout(push_constant) uniform Push {
    vec4 corner;  // xyz: the first point
    vec4 step_x;  // xyz: from one point to the next along a row
    vec4 step_z;  // xyz: from one row to the next
    vec4 normal;  // xyz: the receiver normal at every point
    uint count_x;
    uint count_z;
} pc;

void main() {
    const uint k = gl_GlobalInvocationID.x;
    if (k >= pc.count_x * pc.count_z) return;
    const vec3 p = pc.corner.xyz + float(k % pc.count_x) * pc.step_x.xyz + float(k / pc.count_x) * pc.step_z.xyz;
    probes[k] = vec4(caustic_irradiance(p, pc.normal.xyz), 0.0);
}
