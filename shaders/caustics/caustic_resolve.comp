#version 460
// Fixed-point caustic flux -> irradiance on a plane normal to the sun, E = Phi_texel / A_ls
// (passes/caustics/caustics_resolve.hpp), one band of the held texels' rows per dispatch
// (CausticMapFrame::held: the flux holds them at their own width, the map at their place).
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 0, std430) readonly buffer Flux { uint64_t flux[]; };
layout(set = 0, binding = 1, rgba32f) writeonly uniform image2D irradiance;

layout(push_constant) uniform Push {
    vec4 factor;  // rgb: LSB / A_ls per channel, W m^-2 per unit
    uint width;         // the held texels' columns
    uint band_first;    // the band's first map row
    uint band_rows;
    uint first_column;  // the held texels' first map column
} pc;

void main() {
    const uvec2 g = gl_GlobalInvocationID.xy;
    if (g.x >= pc.width || g.y >= pc.band_rows) return;
    const uint i = (g.y * pc.width + g.x) * 3u;
    const vec3 e = vec3(float(flux[i]), float(flux[i + 1u]), float(flux[i + 2u])) * pc.factor.rgb;
    imageStore(irradiance, ivec2(g.x + pc.first_column, g.y + pc.band_first), vec4(e, 1.0));
}
