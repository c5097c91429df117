// The per-frame optical constants of the water, computed once by
// shaders/water/scene_optics.comp and read by every pass that lights or
// looks through the water.
#ifndef VKWATER_SCENE_OPTICS_GLSL
#define VKWATER_SCENE_OPTICS_GLSL

struct SceneOptics {
    vec4 refracted_sun;  // xyz: the sun's direction below a flat surface (unit, downward); w: cos(theta_t)
    vec4 e_perp0;        // rgb: E_s cos(theta_s) T(theta_s) / cos(theta_t), just below the surface; 0 without sun
    vec4 transmission;   // x: T_hemi(n) (docs/model.md section 1), y: T(theta_s)
};

#endif
