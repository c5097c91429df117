// Shared parts of the caustic tests: the graph water surface -> photons -> resolve (-> probes
// through shaders/caustics/caustic_lookup.glsl) -> readbacks, executed once, and the CPU ground
// truth in double precision (docs/model.md sections 2-4), independent of the photon code.
#pragma once

#include "engine/framegraph/executor.hpp"
#include "engine/framegraph/pass_context.hpp"
#include "engine/vk/resources.hpp"
#include "engine/water/surface.hpp"
#include "passes/caustics/caustics_bands.hpp"
#include "passes/caustics/caustics_blur.hpp"
#include "passes/caustics/caustics_photons.hpp"
#include "passes/caustics/caustics_resolve.hpp"
#include "passes/present/readback.hpp"
#include "passes/receivers/receiver_meshes.hpp"
#include "passes/receivers/sun_shadow.hpp"
#include "passes/water/water_surface.hpp"

#include <glm/glm.hpp>
#include <shader_structs/caustics/caustic_probe.comp.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

namespace vkw::test {

inline constexpr double kUnit = 0x1.0p-24;  // fp32 unit roundoff

// count_x x count_z receiver points corner + a step_x + b step_z, all with `normal`.
struct ProbeGrid {
    glm::dvec3 corner{0.0}, step_x{0.0}, step_z{0.0}, normal{0.0, 1.0, 0.0};
    uint32_t count_x = 0, count_z = 0;
};

struct CausticRun {
    std::vector<uint64_t> flux;     // the fixed-point buffer, header included
    std::vector<float> irradiance;  // W x H x RGBA, the resolved map (blurred, when run with a blur)
    std::vector<float> unblurred;   // W x H x RGBA, the resolved map before the blur (with a blur only)
    std::vector<float> probes;      // count_x x count_z x RGBA: caustic_irradiance at the probes

    uint64_t lost(int c) const { return flux[c]; }
    uint64_t texel(size_t t, int c) const { return flux[passes::kCausticFluxHeaderBytes / 8 + 3 * t + c]; }
};

inline void add_probe_pass(fg::FrameGraph& graph, const passes::CausticMap& map, const ProbeGrid& grid, VkBuffer host,
                           VkDeviceSize bytes) {
    // caustics/caustic_probe.comp's push block, generated from its SPIR-V.
    using Push = glsl::caustic_probe_comp::Push;
    const auto v4 = [](const glm::dvec3& v) { return glm::vec4(glm::vec3(v), 0.0f); };
    Push push{};
    push.corner = v4(grid.corner);
    push.step_x = v4(grid.step_x);
    push.step_z = v4(grid.step_z);
    push.normal = v4(grid.normal);
    push.count_x = grid.count_x;
    push.count_z = grid.count_z;
    struct Data {
        fg::BufferHandle out;
    };
    const auto& data = graph.add_pass<Data>(
        "caustic probes", fg::PassKind::Compute,
        [&](fg::PassBuilder& builder, Data& d) {
            builder.uniform_buffer("CausticMapBlock", map.frame);
            builder.sample("caustic_map", map.irradiance);
            d.out = builder.write_storage("Probes", builder.create_buffer("caustic probes", {bytes}));
        },
        [push](const Data&, fg::PassContext& context) {
            ComputePipelineDesc desc;
            desc.shader = "caustics/caustic_probe.comp";
            desc.layout.bindings = {{0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1, VK_SHADER_STAGE_COMPUTE_BIT},
                                    {1, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, VK_SHADER_STAGE_COMPUTE_BIT},
                                    {2, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_COMPUTE_BIT}};
            desc.layout.push_constant_bytes = sizeof(Push);
            const Pipeline& pipeline = context.pipeline("caustic probes", desc);
            context.bind(pipeline);
            context.push_constants(pipeline, push);
            vkCmdDispatch(context.cmd(), (push.count_x * push.count_z + 63) / 64, 1, 1);
        });
    passes::add_readback_pass(graph, data.out, host, bytes, "probe readback");
}

// The sun shadow map as the renderer fits it: every mesh and the floor square along s, the meshes
// under the water along the caustic map's direction t.
inline passes::SunShadowInputs caustic_shadow_inputs(const passes::CausticInputs& caustics,
                                                     const passes::ReceiverMeshes& meshes, double floor_half_extent,
                                                     double level) {
    passes::SunShadowInputs in;
    in.sun_direction = caustics.sun_direction;
    const double e = floor_half_extent;
    in.bounds_lo = glm::min(meshes.bounds_lo(), glm::dvec3(-e, caustics.floor_height, -e));
    in.bounds_hi = glm::max(meshes.bounds_hi(), glm::dvec3(e, caustics.floor_height, e));
    in.size = 1024;
    in.beam = passes::UnderwaterBeam{passes::fit_caustic_map(caustics).direction, level};
    return in;
}

// Water surface (-> sun shadow map of `meshes`) -> photons -> resolve (-> probes) -> readbacks, one
// submission with validation. With meshes, their sun shadow map (caustic_shadow_inputs) too.
inline CausticRun run_caustics(Context& context, const passes::WaterSurfaceInputs& surface,
                               passes::CausticInputs caustics, const ProbeGrid& probes = {},
                               const passes::ReceiverMeshes* meshes = nullptr, double floor_half_extent = 10.0,
                               double blur_radius = -1.0) {
    // The surface's own grid and extent (before the fit, which sizes the readbacks).
    caustics.grid_resolution = surface.grid_resolution;
    caustics.water_level = surface.level;
    caustics.half_extent = surface.half_extent;
    // The map's own size: the requested W x H plus the margin the waves' crests need.
    const passes::CausticMapFrame frame = passes::fit_caustic_map(caustics);
    const VkDeviceSize flux_bytes = passes::caustic_flux_bytes(frame.width, frame.height);
    const VkDeviceSize image_bytes = VkDeviceSize{frame.width} * frame.height * 16;
    const VkDeviceSize probe_bytes = std::max<VkDeviceSize>(16, VkDeviceSize{probes.count_x} * probes.count_z * 16);
    Buffer flux_host(context, {flux_bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT, true}, "caustic flux readback");
    Buffer image_host(context, {image_bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT, true}, "caustic map readback");
    Buffer unblurred_host(context, {image_bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT, true}, "unblurred map readback");
    Buffer probe_host(context, {probe_bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT, true}, "caustic probe readback");
    {
        fg::PipelineStore pipelines;
        fg::FrameGraph graph;
        caustics.surface = passes::add_water_surface_pass(graph, surface);
        std::optional<passes::SunShadowMap> shadow;
        if (meshes) {
            shadow = passes::add_sun_shadow_pass(
                graph, *meshes, caustic_shadow_inputs(caustics, *meshes, floor_half_extent, surface.level));
        }
        const fg::BufferHandle flux = passes::add_caustic_photon_pass(graph, caustics, shadow ? &*shadow : nullptr);
        passes::CausticMap map = passes::add_caustic_resolve_pass(graph, flux, caustics);
        if (blur_radius >= 0.0) {
            passes::add_readback_pass(graph, map.irradiance, unblurred_host.handle(), image_bytes,
                                      "unblurred readback");
            map = passes::add_caustic_blur_pass(graph, map, caustics, blur_radius);
        }
        passes::add_readback_pass(graph, flux, flux_host.handle(), flux_bytes, "flux readback");
        passes::add_readback_pass(graph, map.irradiance, image_host.handle(), image_bytes, "map readback");
        if (probes.count_x * probes.count_z > 0) add_probe_pass(graph, map, probes, probe_host.handle(), probe_bytes);
        graph.compile(1, 1);
        fg::FrameExecutor executor(context, graph, pipelines, {.check_finite = true, .timing = fg::TimingMode::None});
        executor.execute();
    }
    CausticRun run;
    run.flux.resize(flux_bytes / 8);
    std::memcpy(run.flux.data(), flux_host.mapped(), flux_bytes);
    run.irradiance.resize(image_bytes / 4);
    std::memcpy(run.irradiance.data(), image_host.mapped(), image_bytes);
    if (blur_radius >= 0.0) {
        run.unblurred.resize(image_bytes / 4);
        std::memcpy(run.unblurred.data(), unblurred_host.mapped(), image_bytes);
    }
    run.probes.resize(VkDeviceSize{probes.count_x} * probes.count_z * 4);
    std::memcpy(run.probes.data(), probe_host.mapped(), run.probes.size() * 4);
    return run;
}

// docs/model.md section 2 in double, air to water: T and cos theta_t.
inline double fresnel_t(double cos_i, double n, double* cos_t_out = nullptr) {
    const double cos_t = std::sqrt(std::max(0.0, 1.0 - (1.0 - cos_i * cos_i) / (n * n)));
    const double rs = (cos_i - n * cos_t) / (cos_i + n * cos_t);
    const double rp = (n * cos_i - cos_t) / (n * cos_i + cos_t);
    if (cos_t_out) *cos_t_out = cos_t;
    return 1.0 - 0.5 * (rs * rs + rp * rp);
}

// The sun travelling down at zenith angle `zenith_deg`, its horizontal part along `azimuth`.
inline glm::dvec3 sun_at(double zenith_deg, const glm::dvec3& azimuth) {
    const double a = zenith_deg * 3.14159265358979323846 / 180.0;
    return glm::normalize(glm::dvec3(0.0, -std::cos(a), 0.0) + std::sin(a) * azimuth);
}

// Where a section 4 integral counts photons: those landing on the floor with x in [x_lo, x_hi]
// (the whole floor by default), over a strip of z_width metres (0: the whole square, 2E).
struct LandingWindow {
    double x_lo = -1e300, x_hi = 1e300;
    double z_width = 0.0;
};

// docs/model.md section 4 over the grid's whole parameter square [-E, E]^2 of a surface that varies
// only along x0 (a sine along x): per RGB, E_s * integral of max(0, -s.N) |dP/du x dP/dv|
// T(theta_i) exp(-sigma_t l) dx0 dz0, midpoint rule with `samples` points along x0 in double,
// restricted to the photons landing in `window` (a sun in the xy-plane keeps z: a strip in z is
// its width times the integral along x0).
// With `intercepted_only` the integrand stops at the intercepted flux (T = 1, no extinction).
inline glm::dvec3 section4_flux(const WaterSurface& surface, const passes::CausticInputs& in, int samples,
                                bool intercepted_only = false, const LandingWindow& window = {}) {
    const double e = in.half_extent, dx = 2.0 * e / samples;
    glm::dvec3 sum(0.0);
    for (int k = 0; k < samples; ++k) {
        const SurfacePoint p = surface.at_parameter(-e + (k + 0.5) * dx, 0.0);
        const glm::dvec3 area = glm::cross(p.dP_dv, p.dP_du);  // up for the grid's orientation
        const double projected = -glm::dot(in.sun_direction, area);
        const double cos_i = -glm::dot(in.sun_direction, p.normal);
        if (!(projected > 0.0) || !(cos_i > 0.0)) continue;
        if (intercepted_only) {
            sum += in.sun_irradiance * projected;
            continue;
        }
        double cos_t = 0.0;
        const double t_factor = fresnel_t(cos_i, in.ior, &cos_t);
        const double eta = 1.0 / in.ior;
        const glm::dvec3 t = eta * in.sun_direction + (eta * cos_i - cos_t) * p.normal;
        if (t.y > -1e-6) continue;
        const double l = (p.position.y - in.floor_height) / -t.y;
        const double x_hit = p.position.x + l * t.x;
        if (x_hit < window.x_lo || x_hit > window.x_hi) continue;
        sum += in.sun_irradiance * projected * t_factor * glm::exp(-in.sigma_t * l);
    }
    return sum * dx * (window.z_width > 0.0 ? window.z_width : 2.0 * e);
}

}  // namespace vkw::test
