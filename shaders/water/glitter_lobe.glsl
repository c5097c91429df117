// The sun's glitter lobe as a pure function of its inputs (water/sun_glitter.glsl supplies them from
// the frame; shaders/tests/glitter_sweep.comp from a test). Facets whose slopes z = (-n_x / n_y,
// -n_z / n_y) are Gaussian, of mean `mean_slope` and covariance (S_xx, S_xz, S_zz), over a unit of
// the horizontal plane reflect a directional source of unit irradiance (on a plane normal to it)
// toward the eye with radiance
//     L = F(o.h) p(z_h) / (4 o_y h_y^4)   (times Smith's visibility, below)
// where o is the direction to the eye, l the one to the source, h = normalize(l + o) and z_h its
// slope. Without the visibility this reflects exactly the flux the facets intercept: the integral
// of L o_y over the eye's hemisphere is that of F(l.h) (l.h) / h_y p(z) over the slopes that send
// the light up (tests/optics/glitter_test.cpp). Near the horizon facets hide one another from the
// eye and the source: Smith's 1 / (1 + Lambda(o) + Lambda(l)) for Gaussian slopes (Bruneton, Neyret
// and Holzschuch 2010, eq. 14) removes that light.
#ifndef VKWATER_GLITTER_LOBE_GLSL
#define VKWATER_GLITTER_LOBE_GLSL

const float GLITTER_PI = 3.14159265358979323846;

// Smith's Lambda for Gaussian slopes of covariance (S_xx, S_xz, S_zz), seen along `direction`:
// (exp(-a^2) / (a sqrt(pi)) - erfc(a)) / 2 with a = cot(theta) / (sqrt(2) sigma), sigma^2 the slopes'
// variance along the direction's horizontal part. erfc by Abramowitz and Stegun 7.1.26 (absolute
// error below 1.5e-7); past a = 6 Lambda is below 1e-17 and taken as 0.
float smith_lambda(vec3 direction, vec3 covariance) {
    const float horizontal = length(direction.xz);
    if (!(horizontal > 0.0) || !(direction.y > 0.0)) return 0.0;
    const vec2 u = direction.xz / horizontal;
    const float variance = covariance.x * u.x * u.x + 2.0 * covariance.y * u.x * u.y + covariance.z * u.y * u.y;
    const float a = direction.y / (horizontal * sqrt(2.0 * max(variance, 1e-12)));
    if (a > 6.0) return 0.0;
    const float t = 1.0 / (1.0 + 0.3275911 * a);
    const float erfc_a =
        t * (0.254829592 + t * (-0.284496736 + t * (1.421413741 + t * (-1.453152027 + t * 1.061405429)))) * exp(-a * a);
    return max(0.0, 0.5 * (exp(-a * a) / (a * sqrt(GLITTER_PI)) - erfc_a));
}

// The half vector between the source and the eye (toward both).
vec3 glitter_half_vector(vec3 to_eye, vec3 to_source) { return normalize(to_source + to_eye); }

// L per unit source irradiance, without the visibility; `reflectance`: F at dot(to_eye, h).
float glitter_lobe(vec3 to_eye, vec3 to_source, vec2 mean_slope, vec3 covariance, float reflectance) {
    if (!(to_eye.y > 0.0) || !(to_source.y > 0.0)) return 0.0;
    const vec3 h = glitter_half_vector(to_eye, to_source);
    if (!(h.y > 0.0)) return 0.0;
    const vec2 delta = -h.xz / h.y - mean_slope;
    const float det = covariance.x * covariance.z - covariance.y * covariance.y;
    const float q =
        (covariance.z * delta.x * delta.x - 2.0 * covariance.y * delta.x * delta.y + covariance.x * delta.y * delta.y) /
        det;
    const float density = exp(-0.5 * q) / (2.0 * GLITTER_PI * sqrt(det));
    const float h2 = h.y * h.y;
    return reflectance * density / (4.0 * to_eye.y * h2 * h2);
}

// Smith's visibility of the facets from the eye and the source together.
float glitter_visibility(vec3 to_eye, vec3 to_source, vec3 covariance) {
    return 1.0 / (1.0 + smith_lambda(to_eye, covariance) + smith_lambda(to_source, covariance));
}

#endif
