#version 450
// The frame's resolution scale (passes/frame/upscale.hpp): the scene's image stretched over the
// output with the bilinear filter.

layout(binding = 0) uniform sampler2D source;
layout(push_constant) uniform Push {
    float inverse_width;   // 1 / the output's width
    float inverse_height;  // 1 / the output's height
} push;

layout(location = 0) out vec4 out_colour;

void main() {
    // The output pixel's centre as a fraction of the image: the same fraction of the source,
    // where the sampler weighs the four source pixels around it.
    const vec2 fraction = gl_FragCoord.xy * vec2(push.inverse_width, push.inverse_height);
    out_colour = texture(source, fraction);
}
