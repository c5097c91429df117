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

// The Gaussian density of the facets' slopes at z_h = -h.xz / h.y, the slope of the facet normal h
// (per unit of slope, per unit of the horizontal plane); D(h) = p(z_h) / h_y^4 per solid angle.
float glitter_slope_density(vec3 h, vec2 mean_slope, vec3 covariance) {
    const vec2 delta = -h.xz / h.y - mean_slope;
    const float det = covariance.x * covariance.z - covariance.y * covariance.y;
    const float q =
        (covariance.z * delta.x * delta.x - 2.0 * covariance.y * delta.x * delta.y + covariance.x * delta.y * delta.y) /
        det;
    return exp(-0.5 * q) / (2.0 * GLITTER_PI * sqrt(det));
}

// L per unit source irradiance, without the visibility; `reflectance`: F at dot(to_eye, h).
float glitter_lobe(vec3 to_eye, vec3 to_source, vec2 mean_slope, vec3 covariance, float reflectance) {
    if (!(to_eye.y > 0.0) || !(to_source.y > 0.0)) return 0.0;
    const vec3 h = glitter_half_vector(to_eye, to_source);
    if (!(h.y > 0.0)) return 0.0;
    const float h2 = h.y * h.y;
    return reflectance * glitter_slope_density(h, mean_slope, covariance) / (4.0 * to_eye.y * h2 * h2);
}

// The refraction's half vector (Walter et al. 2007): the facet normal, toward the
// air, that bends the source's light (from direction `to_source`, in the air, index 1) toward an eye
// in the water (index n) along `to_eye`, which points down.
vec3 glitter_refraction_half_vector(vec3 to_eye, vec3 to_source, float n) {
    return normalize(-(to_source + n * to_eye));
}

// The same facets seen from the water: L per unit source irradiance, transmitted toward an eye below
// along `to_eye` (pointing down), without the visibility; `transmittance`: T at dot(to_source, h).
//     L = T (l.h) |o.h| n^2 p(z_h) / (|o_y| h_y^4 |l + n o|^2)
// (Walter et al. 2007's BTDF times l_y, with D(h) = p(z_h) / h_y^4 and the denominator
// (l.h + n o.h)^2 = |l + n o|^2). The n^2 is the radiance's gain across the surface (docs/model.md
// section 2). Without the visibility it transmits exactly the flux the facets let through: the
// integral of L |o_y| over the eye's lower hemisphere is that of T(l.h) (l.h) / h_y p(z) over the
// slopes (tests/optics/glitter_test.cpp).
float glitter_transmission_lobe(vec3 to_eye, vec3 to_source, float n, vec2 mean_slope, vec3 covariance,
                                float transmittance) {
    if (!(to_eye.y < 0.0) || !(to_source.y > 0.0)) return 0.0;
    const vec3 bent = to_source + n * to_eye;
    const vec3 h = glitter_refraction_half_vector(to_eye, to_source, n);
    const float lh = dot(to_source, h), oh = dot(to_eye, h);
    if (!(h.y > 0.0) || !(lh > 0.0) || !(oh < 0.0)) return 0.0;
    const float h2 = h.y * h.y;
    return transmittance * lh * (-oh) * n * n * glitter_slope_density(h, mean_slope, covariance) /
           (-to_eye.y * h2 * h2 * dot(bent, bent));
}

// Smith's visibility of the facets from the eye and the source together.
float glitter_visibility(vec3 to_eye, vec3 to_source, vec3 covariance) {
    return 1.0 / (1.0 + smith_lambda(to_eye, covariance) + smith_lambda(to_source, covariance));
}

#endif
