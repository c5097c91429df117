// Fresnel reflectance of a perfect dielectric interface (docs/model.md section 2), for
// unpolarised light, from either side. The one place in the shaders where R and T are
// computed; every pass that crosses the water surface includes this file.
#ifndef VKWATER_FRESNEL_GLSL
#define VKWATER_FRESNEL_GLSL

struct Fresnel {
    float R;        // reflectance
    float T;        // transmittance, 1 - R
    float cos_t;    // cosine of the refraction angle (0 under total internal reflection)
    bool total_internal_reflection;
};

// cos_i: cosine between the incoming ray and the normal on the incoming side (clamped
// to [0, 1]); n_i, n_t: indices of refraction of the incoming and transmitting media.
// Total internal reflection gives R = 1 and T = 0 exactly.
Fresnel fresnel_exact(float cos_i, float n_i, float n_t) {
    cos_i = clamp(cos_i, 0.0, 1.0);
    float eta = n_i / n_t;
    float sin2_t = eta * eta * max(0.0, 1.0 - cos_i * cos_i);
    if (sin2_t >= 1.0) return Fresnel(1.0, 0.0, 0.0, true);
    float cos_t = sqrt(max(0.0, 1.0 - sin2_t));
    // Neither denominator can be 0 here: cos_t > 0, and cos_i = 0 only leaves n * cos_t > 0.
    float r_s = (n_i * cos_i - n_t * cos_t) / (n_i * cos_i + n_t * cos_t);
    float r_p = (n_t * cos_i - n_i * cos_t) / (n_t * cos_i + n_i * cos_t);
    float R = clamp(0.5 * (r_s * r_s + r_p * r_p), 0.0, 1.0);
    return Fresnel(R, 1.0 - R, cos_t, false);
}

// Schlick's approximation. It is accurate only with the cosine on the less dense side,
// so from the denser side (n_i > n_t) it uses cos_t; total internal reflection is exact.
Fresnel fresnel_schlick(float cos_i, float n_i, float n_t) {
    Fresnel exact = fresnel_exact(cos_i, n_i, n_t);  // for cos_t and the TIR test
    if (exact.total_internal_reflection) return exact;
    float r0 = (n_i - n_t) / (n_i + n_t);
    r0 *= r0;
    float c = n_i <= n_t ? clamp(cos_i, 0.0, 1.0) : exact.cos_t;
    float m = 1.0 - c;
    float R = r0 + (1.0 - r0) * (m * m) * (m * m) * m;
    return Fresnel(R, 1.0 - R, exact.cos_t, false);
}

// Refracts the unit direction I at the unit normal N (N on the side I comes from,
// dot(I, N) < 0), eta = n_i / n_t. Returns false under total internal reflection,
// where GLSL's refract() would return a zero vector (never normalise that).
bool refract_direction(vec3 I, vec3 N, float eta, out vec3 T) {
    float cos_i = -dot(I, N);
    float k = 1.0 - eta * eta * (1.0 - cos_i * cos_i);
    if (k < 0.0) {
        T = vec3(0.0);
        return false;
    }
    T = normalize(eta * I + (eta * cos_i - sqrt(k)) * N);
    return true;
}

#endif
