    // scene_hit_filter.sh's "stepped" variant of filter_hit (shaders/water/scene_lookup.glsl): one
    // more fixed-point step on the bilinear surface, then the read where the ray's point projects.
    const float s = max(0.0, dot(scene_view_point(uv, value.a, mirrored) - p, d));
    vec2 stepped_uv;
    ivec2 stepped_base;
    vec4 stepped_weights, stepped_value;
    if (scene_view_uv(p + s * d, mirrored, stepped_uv) &&
        read_hit_surface(view, hit.peeled, stepped_uv, hit.shown, stepped_base, stepped_weights,
                                    stepped_value)) {
        hit.distance = s;
        base = stepped_base;
        weights = stepped_weights;
        value = stepped_value;
    }
