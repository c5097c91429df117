// How far a ray in infinite water that meets no receiver runs (docs/model.md section 1, "Infinite
// water"): down to the water's bottom, where nothing is lit, and no farther than the far field's
// distance from its origin, measured horizontally, so that a grazing ray's length stays finite.
// A ray that does not point down meets the surface in that model, never the bottom: 0.
#ifndef VKWATER_WATER_BOTTOM_GLSL
#define VKWATER_WATER_BOTTOM_GLSL

float run_to_water_bottom(vec3 origin, vec3 d, float bottom_y, float far_field) {
    if (!(d.y < 0.0)) return 0.0;
    const float to_bottom = (bottom_y - origin.y) / d.y;
    const float horizontal = length(d.xz);
    const float to_far_field = horizontal > 0.0 ? far_field / horizontal : to_bottom;
    return max(min(to_bottom, to_far_field), 0.0);
}

#endif
