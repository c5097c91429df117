#version 450
// Depth only: keeps the parts of the meshes under the half's clip height (the beam half of
// passes/receivers/sun_shadow.hpp holds only what lies under the water; the sun half keeps everything).
// Variant VKWATER_CUTOUT (scenes with glTF alphaMode MASK parts): a cutout casts no shadow where its
// alpha falls below its threshold, as receivers/receiver.frag leaves it out of the view.
layout(location = 0) in float in_height;
layout(location = 1) in vec2 in_uv;
layout(location = 2) in float in_alpha;
layout(push_constant) uniform SunShadowPush {
    mat4 light_from_world;
    vec4 clip;
    vec4 material;
} push;
#ifdef VKWATER_CUTOUT
layout(set = 0, binding = 8) uniform sampler2D base_color_texture;
#endif

void main() {
    if (in_height > push.clip.x) discard;
#ifdef VKWATER_CUTOUT
    if (texture(base_color_texture, in_uv).a * in_alpha * push.material.x < push.material.y) discard;
#endif
}
