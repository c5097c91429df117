#version 450
// Frame-graph test: copies the sampled image texel for texel (texelFetch, no
// filtering) and doubles it, so the output proves the sample happened after the write.
layout(set = 0, binding = 0) uniform sampler2D source;
layout(location = 0) out vec4 out_color;

void main() {
    out_color = 2.0 * texelFetch(source, ivec2(gl_FragCoord.xy), 0);
}
