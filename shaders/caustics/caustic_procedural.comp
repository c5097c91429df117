#version 460
// Guardado & Sánchez-Crespo 2004's procedural caustic, one texel of the light-space caustic map per invocation
// (passes/caustics/caustics_procedural.hpp says what and why).
#extension GL_GOOGLE_include_directive : require

#include "common/fresnel.glsl"
#include "water/water_vertex.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 0, std430) readonly buffer Surface { WaterVertex vertices[]; };
layout(set = 0, binding = 1, rgba32f) writeonly uniform image2D irradiance;

layout(push_constant) uniform Push {
    vec4 e_floor;   // rgb: E_perp under flat water at the floor, W m^-2
    vec4 sun;       // xyz: the direction the sunlight travels; w: n
    vec4 t;         // xyz: the flat-water refracted sun; w: the mean level
    vec2 corner;    // (x, z) at the mean level of texel coordinate (0, 0), m
    vec2 texel;     // m
    float half_extent;
    uint resolution;
    uint width, height;
} pc;

const float kLobeRadians = 4.0 * 3.14159265 / 180.0;  // the blurred sun's angular radius

// The water's normal over grid parameter (x, z), bilinear between the four vertices around it.
vec3 normal_at(vec2 xz) {
    const float r = float(pc.resolution);
    const vec2 a = clamp((xz + pc.half_extent) / (2.0 * pc.half_extent) * r, vec2(0.0), vec2(r));
    const uvec2 cell = min(uvec2(a), uvec2(pc.resolution - 1u));
    const vec2 f = a - vec2(cell);
    const uint row = pc.resolution + 1u;
    const uint k = cell.y * row + cell.x;
    const vec3 n0 = mix(vertices[k].normal.xyz, vertices[k + 1u].normal.xyz, f.x);
    const vec3 n1 = mix(vertices[k + row].normal.xyz, vertices[k + row + 1u].normal.xyz, f.x);
    return normalize(mix(n0, n1, f.y));
}

void main() {
    const uvec2 g = gl_GlobalInvocationID.xy;
    if (g.x >= pc.width || g.y >= pc.height) return;
    const vec2 xz = pc.corner + (vec2(g) + 0.5) * pc.texel;
    vec3 e = vec3(0.0);
    if (all(lessThanEqual(abs(xz), vec2(pc.half_extent)))) {
        // The backward ray: up along -t through the surface there, refracted into the air (n to 1;
        // refract_direction wants the normal on the incoming side, here the water's).
        const vec3 up_normal = normal_at(xz);
        vec3 to_air;
        if (refract_direction(-pc.t.xyz, -up_normal, pc.sun.w, to_air)) {
            const float cos_angle = clamp(dot(to_air, -pc.sun.xyz), -1.0, 1.0);
            const float angle = acos(cos_angle) / kLobeRadians;
            e = pc.e_floor.rgb * exp(-angle * angle);
        }
    }
    imageStore(irradiance, ivec2(g), vec4(e, 1.0));
}
