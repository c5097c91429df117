#version 450
// vkwater's frame into a host's colour target (passes/present/host_composite.hpp): the HDR
// radiance as it is (linear, before exposure: the host tone-maps), at the depth of the surface it
// shows, which the pipeline's depth test (reverse Z, greater or equal) weighs against the host's.

layout(binding = 0) uniform sampler2D hdr;
layout(binding = 1) uniform sampler2D scene_depth;

layout(location = 0) out vec4 color;

void main() {
    const ivec2 pixel = ivec2(gl_FragCoord.xy);
    color = vec4(texelFetch(hdr, pixel, 0).rgb, 1.0);
    // The scene depth is at the scene's render scale; the HDR colour at the target's size.
    const vec2 scale = vec2(textureSize(scene_depth, 0)) / vec2(textureSize(hdr, 0));
    gl_FragDepth = texelFetch(scene_depth, ivec2(gl_FragCoord.xy * scale), 0).r;
}
