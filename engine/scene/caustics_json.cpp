// The settings of "effects.caustics" beside its mode (effects_json.cpp reads the mode): whether
// flat water keeps the exact stand-in, the photons per water cell, their splat kernel and where
// they are splatted (the light-space map or the camera's view); and
// of "effects.caustic_blur": its radius.
#include "engine/scene/scene_json.hpp"

#include <array>

namespace vkw {
namespace {

constexpr std::array<Named<CausticKernel>, 3> kKernels = {{
    {"adaptive", CausticKernel::Adaptive},
    {"bilinear", CausticKernel::Bilinear},
    {"footprint", CausticKernel::Footprint},
}};

constexpr std::array<Named<CausticSplat>, 2> kSplats = {{
    {"light-space", CausticSplat::LightSpace},
    {"camera-space", CausticSplat::CameraSpace},
}};

constexpr std::array<Named<CausticMethod>, 2> kMethods = {{
    {"photons", CausticMethod::Photons},
    {"procedural", CausticMethod::Procedural},
}};

}  // namespace

const char* caustic_kernel_name(CausticKernel kernel) {
    for (const auto& named : kKernels) {
        if (named.value == kernel) return named.name.data();  // a literal: terminated
    }
    return "";
}

CausticSettings read_caustic_settings(FieldReader& fields) {
    const CausticSettings defaults;
    CausticSettings caustics;
    caustics.method = fields.choice("method", kMethods, defaults.method);
    caustics.analytic_flat = fields.boolean("analytic_flat", defaults.analytic_flat);
    caustics.sub_photons = static_cast<uint32_t>(
        fields.integer("sub_photons", Range::closed(1.0, 8.0, "photons per cell side"), defaults.sub_photons));
    caustics.jitter = fields.boolean("jitter", defaults.jitter);
    caustics.cull = fields.boolean("cull", defaults.cull);
    caustics.kernel = fields.choice("kernel", kKernels, defaults.kernel);
    caustics.splat = fields.choice("splat", kSplats, defaults.splat);
    caustics.map_scale =
        fields.number("map_scale", Range::closed(0.25, 4.0, "texels per water cell"), defaults.map_scale);
    fields.finish();
    if (caustics.splat == CausticSplat::CameraSpace && caustics.method != CausticMethod::Photons) {
        fields.fail("splat", "camera-space splats gather the photons' flux, so they need method \"photons\"",
                    "light-space with method \"procedural\"");
    }
    return caustics;
}

CausticBlurSettings read_caustic_blur_settings(FieldReader& fields) {
    const CausticBlurSettings defaults;
    CausticBlurSettings blur;
    blur.radius = fields.number("radius", Range::closed(0.0, 4.0, "texels"), defaults.radius);
    fields.finish();
    return blur;
}

}  // namespace vkw
