// The water's per-pixel refinement (shaders/water/surface_refinement.glsl) against the CPU: the
// water's mesh is drawn with a probe shader that writes the point each pixel shows, and each
// drawn pixel's point is compared with the first crossing of the pixel's ray with the same
// surface in double precision (bracketed along the ray, then bisected, as the reference
// renderer finds it). Sums of sines, Gerstner waves and the choppy FFT ocean, each from above
// and from below the surface.
#include "engine/framegraph/executor.hpp"
#include "engine/framegraph/pass_context.hpp"
#include "engine/vk/resources.hpp"
#include "engine/water/wave_sum_surface.hpp"
#include "passes/common/frame_constants.hpp"
#include "passes/common/frame_constants_upload.hpp"
#include "passes/common/frame_keys.hpp"
#include "passes/present/readback.hpp"
#include "passes/water/water_screen_mesh.hpp"
#include "passes/water/water_shading.hpp"
#include "passes/water/water_surface.hpp"
#include "passes/water/water_surface_draw.hpp"
#include "passes/water/water_surface_spectrum.hpp"
#include "tests/support/gpu_test.hpp"
#include "tests/water_gpu/ocean_reference.hpp"
#include "tests/water_gpu/wave_sum_tolerance.hpp"

#include <gtest/gtest.h>
#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <functional>
#include <memory>
#include <numbers>
#include <optional>
#include <random>
#include <vector>

namespace vkw::test {
namespace {

constexpr uint32_t kWidth = 160, kHeight = 120;
const uint32_t kRefineSteps = passes::WaterSurfaceShading{}.refine_steps;  // the shading's default
// The shader's acceptance: a refined point misses the ray by at most this times (1 + t).
constexpr double kRefinementRelativeTolerance = 1e-5;

// The surface point at a grid parameter and the GPU's fp32 tolerance there.
using CpuSurface = std::function<std::pair<SurfacePoint, VertexTolerance>(double x0, double z0)>;

// Draws the water's mesh with tests/water_refinement_probe.frag and reads back, per pixel, the
// point it shows (w = 1 refined, 0.5 the mesh's point, 0 no water).
std::vector<glm::vec4> probe_pixels(Context& gpu, const FrameConstants& constants,
                                    const passes::WaterSurfaceInputs& inputs, uint32_t mesh_resolution,
                                    const passes::ScreenMesh& screen) {
    const VkDeviceSize bytes = VkDeviceSize{kWidth} * kHeight * sizeof(glm::vec4);
    Buffer readback(gpu, {bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT, true}, "refinement probe readback");
    {
        fg::PipelineStore pipelines;
        fg::FrameGraph graph;
        passes::add_frame_constants_upload(graph, &constants);
        const passes::WaterSurfaceBuffers surface =
            passes::add_water_surface_passes(graph, inputs, mesh_resolution, screen);
        struct Data {
            passes::WaterSurfaceReads surface;
            fg::ImageHandle points, depth;
        };
        const auto& data = graph.add_pass<Data>(
            "refinement probe", fg::PassKind::Graphics,
            [&](fg::PassBuilder& builder, Data& d) {
                builder.uniform_buffer("FrameConstants", graph.blackboard().get(keys::kFrameConstants),
                                       VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT | VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT);
                d.surface.declare(builder, surface);
                d.points = builder.color_attachment(builder.create_image("probe points", {}), fg::LoadOp::Clear);
                d.depth = builder.depth_stencil_attachment(builder.create_image("probe depth", {VK_FORMAT_D32_SFLOAT}),
                                                           fg::LoadOp::Clear, {.depth = 0.0f});
            },
            [push = passes::water_surface_push(surface, kRefineSteps)](const Data& d, fg::PassContext& context) {
                GraphicsPipelineDesc desc;
                desc.vertex_shader = d.surface.vertex_shader();
                desc.fragment_shader = "tests/water_refinement_probe.frag";
                desc.depth_test = true;
                desc.depth_write = true;
                desc.topology = passes::WaterSurfaceReads::kTopology;
                const std::string key = d.surface.specialise(desc, "refinement probe");
                const Pipeline& pipeline = context.pipeline(key, desc);
                context.bind(pipeline, d.surface.stand_ins(context));
                d.surface.draw(context, pipeline, push);
            });
        passes::add_readback_pass(graph, data.points, readback.handle(), bytes);
        graph.compile(kWidth, kHeight);
        fg::FrameExecutor executor(gpu, graph, pipelines, {.check_finite = true, .timing = fg::TimingMode::None});
        executor.execute();
    }
    std::vector<glm::vec4> pixels(kWidth * kHeight);
    std::memcpy(pixels.data(), readback.mapped(), bytes);
    return pixels;
}

// The ray through the centre of pixel (x, y) as common/camera_ray.glsl builds it (row 0 at the
// top), in double from the frame's fp32 matrix.
glm::dvec3 pixel_ray(const FrameConstants& constants, uint32_t x, uint32_t y) {
    const glm::dvec2 ndc(2.0 * (x + 0.5) / kWidth - 1.0, 1.0 - 2.0 * (y + 0.5) / kHeight);
    const glm::dvec4 near = glm::dmat4(constants.inv_view_proj) * glm::dvec4(ndc, 1.0, 1.0);
    return glm::normalize(glm::dvec3(near) / near.w - glm::dvec3(constants.camera_position));
}

// The grid parameter whose point lies above or below world (x, z): Newton on the horizontal
// map from `start`, as WaterSurface::parameter_at (heightfields converge in one step).
glm::dvec2 parameter_below(const CpuSurface& surface, double x, double z, glm::dvec2 start) {
    glm::dvec2 u = start;
    for (int i = 0; i < 50; ++i) {
        const SurfacePoint p = surface(u.x, u.y).first;
        const glm::dvec2 miss(p.position.x - x, p.position.z - z);
        if (glm::length(miss) <= 1e-13) break;
        const glm::dmat2 jacobian(p.dP_du.x, p.dP_du.z, p.dP_dv.x, p.dP_dv.z);  // columns
        u -= glm::inverse(jacobian) * miss;
    }
    return u;
}

struct Crossing {
    double t;
    glm::dvec2 parameter;
};

// The first crossing of eye + t d with the surface: the ray's height above the surface is
// bracketed by steps of `step` metres through the slab |y - level| <= amplitude, then bisected
// to 1e-13 m.
std::optional<Crossing> first_crossing(const CpuSurface& surface, const glm::dvec3& eye, const glm::dvec3& d,
                                       double level, double amplitude, double step) {
    double t0 = 0.0, t1 = 400.0;
    if (std::abs(d.y) > 1e-12) {
        const double a = (level + amplitude - eye.y) / d.y, b = (level - amplitude - eye.y) / d.y;
        t0 = std::max(0.0, std::min(a, b));
        t1 = std::min(t1, std::max(a, b));
    }
    glm::dvec2 u(eye.x + t0 * d.x, eye.z + t0 * d.z);
    auto height_above = [&](double t, glm::dvec2& start) {
        const glm::dvec3 q = eye + t * d;
        start = parameter_below(surface, q.x, q.z, start);
        return q.y - surface(start.x, start.y).first.position.y;
    };
    const double sign = height_above(t0, u) > 0.0 ? 1.0 : -1.0;
    for (double lo = t0; lo < t1; lo += step) {
        glm::dvec2 u_hi = u;
        const double hi = std::min(lo + step, t1);
        if (sign * height_above(hi, u_hi) > 0.0) {
            u = u_hi;
            continue;
        }
        double a = lo, b = hi;
        while (b - a > 1e-13) {
            const double mid = 0.5 * (a + b);
            glm::dvec2 u_mid = u;
            if (sign * height_above(mid, u_mid) > 0.0) {
                a = mid;
                u = u_mid;
            } else {
                b = mid;
            }
        }
        glm::dvec2 u_end = u;
        height_above(b, u_end);
        return Crossing{b, u_end};
    }
    return std::nullopt;
}

struct RefinementCase {
    glm::dvec3 eye, target;
    double level, half_extent, amplitude;  // amplitude: a bound on |P.y - level|
    double shortest_wavelength;            // m: the bracketing steps 1/64 of it
    double max_second_derivative;          // of P per unit of parameter squared: the mesh's sag
    uint32_t mesh_resolution;
    // > 0: drawn from the screen's grid with cells this many pixels wide instead of the uniform
    // mesh; its coarsest cells' sag is bounded by the slab, 2 amplitude (the vertex shader's cap).
    uint32_t screen_cell_pixels = 0;
};

// Samples drawn pixels and compares each with the CPU crossing. A refined pixel's point q lies
// within a = tau + e_ray of the ray (tau the shader's acceptance, 1e-5 (1 + t); e_ray the gap
// between the GPU's ray through the interpolated mesh point and the CPU's through the pixel
// centre, 16 u (t + |eye|)) and within b = |tolerance| of the surface (the GPU's fp32 error of
// P there); locally the surface is a plane with normal n, so q is within (a + b) / |d.n| + a of
// the crossing (curvature adds (1e-4 m)^2 / radius, below 1e-7 m here). At least 99.5% of the
// drawn pixels must meet that; every pixel, within one mesh cell's sag, h^2 / 8 times the
// largest second derivative (h the cell's diagonal), over |d.n|, plus the same bound.
void expect_refined_surface(Context& context, const passes::WaterSurfaceInputs& inputs, const CpuSurface& surface,
                            const RefinementCase& c) {
    Scene scene;
    scene.camera.position = c.eye;
    scene.camera.target = c.target;
    scene.camera.fov_y_deg = 50.0;
    scene.water = Water{};
    scene.water->level = c.level;
    scene.water->half_extent = c.half_extent;
    const FrameConstants constants = make_frame_constants(scene, kWidth, kHeight);
    const passes::ScreenMesh screen =
        passes::screen_mesh(c.screen_cell_pixels, scene.camera, double(kWidth) / kHeight, c.level, c.amplitude);
    const std::vector<glm::vec4> pixels = probe_pixels(context, constants, inputs, c.mesh_resolution, screen);

    const double cell = 2.0 * c.half_extent / c.mesh_resolution;
    const double sag =
        c.screen_cell_pixels > 0 ? 2.0 * c.amplitude : (2.0 * cell * cell / 8.0) * c.max_second_derivative;
    constexpr int kSamples = 3000;
    std::mt19937 random(1234);
    std::uniform_int_distribution<uint32_t> pick(0, kWidth * kHeight - 1);
    uint32_t drawn = 0, refined = 0, within = 0, crossings = 0, missed = 0;
    double worst_ratio = 0.0, largest_bound = 0.0;
    for (int sample = 0; sample < kSamples; ++sample) {
        const uint32_t index = pick(random);
        const glm::vec4 gpu = pixels[index];
        if (gpu.w == 0.0f) {
            // Not drawn: the pixel's ray must meet no water, or meet it within a mesh cell of the
            // square's edge (the uniform mesh's edge is its cells' chords; a cell of the screen's
            // grid there is smaller). A grid that stopped short of the viewport's edge, or whose
            // margin the waves overran, leaves such pixels.
            const std::optional<Crossing> cpu =
                first_crossing(surface, c.eye, pixel_ray(constants, index % kWidth, index / kWidth), c.level,
                               c.amplitude, c.shortest_wavelength / 64.0);
            const double inner = c.half_extent - cell;
            if (cpu && std::abs(cpu->parameter.x) < inner && std::abs(cpu->parameter.y) < inner) {
                ++missed;
                ADD_FAILURE() << "pixel (" << index % kWidth << ", " << index / kWidth
                              << ") shows no water, but its ray meets the surface at parameter (" << cpu->parameter.x
                              << ", " << cpu->parameter.y << ")";
            }
            continue;
        }
        ++drawn;
        refined += gpu.w == 1.0f;
        const glm::dvec3 d = pixel_ray(constants, index % kWidth, index / kWidth);
        const std::optional<Crossing> cpu =
            first_crossing(surface, c.eye, d, c.level, c.amplitude, c.shortest_wavelength / 64.0);
        if (!cpu) {
            ADD_FAILURE() << "pixel " << index << ": drawn, but its ray meets no water on the CPU";
            continue;
        }
        ++crossings;
        const auto [point, tolerance] = surface(cpu->parameter.x, cpu->parameter.y);
        const double cosine = std::abs(glm::dot(d, point.normal));
        const double a =
            kRefinementRelativeTolerance * (1.0 + cpu->t) + 16.0 * kUnitRoundoff * (cpu->t + glm::length(c.eye));
        const double bound = (a + glm::length(tolerance.position)) / cosine + a;
        const double error = glm::length(glm::dvec3(gpu) - (c.eye + cpu->t * d));
        largest_bound = std::max(largest_bound, bound);
        if (error <= bound) {
            ++within;
            worst_ratio = std::max(worst_ratio, error / bound);
        } else {
            // The rest: crossings the mesh could not resolve. From the true first crossing to
            // the point shown, the ray may dip into the other medium only as deep as the mesh's
            // chords can lie from the surface (a crest thinner than the sag, or the mesh's own
            // point kept), and the point shown lies within the sag of the surface. Depths are
            // distances to the surface: the height difference times the normal's y (the
            // surface is locally a plane; a choppy wave's steep side is close in distance long
            // before it is in height).
            const double t_shown = glm::length(glm::dvec3(gpu) - c.eye);
            const double side = c.eye.y > c.level ? 1.0 : -1.0;
            double deepest = 0.0;
            glm::dvec2 u = cpu->parameter;
            const double t_end = std::max(t_shown, cpu->t);
            for (double t = std::min(t_shown, cpu->t); t <= t_end; t += c.shortest_wavelength / 256.0) {
                const glm::dvec3 q = c.eye + t * d;
                u = parameter_below(surface, q.x, q.z, u);
                const SurfacePoint below = surface(u.x, u.y).first;
                deepest = std::max(deepest, -side * (q.y - below.position.y) * below.normal.y);
            }
            const glm::dvec3 shown(gpu);
            u = parameter_below(surface, shown.x, shown.z, u);
            const SurfacePoint under_shown = surface(u.x, u.y).first;
            const double off_surface = std::abs(shown.y - under_shown.position.y) * under_shown.normal.y;
            EXPECT_LE(deepest, sag + bound)
                << "pixel (" << index % kWidth << ", " << index / kWidth << "), refined " << (gpu.w == 1.0f)
                << ", first crossing at t = " << cpu->t << " m, shown at " << t_shown << " m";
            EXPECT_LE(off_surface, sag + bound) << "pixel (" << index % kWidth << ", " << index / kWidth << ")";
        }
    }
    std::printf(
        "%u drawn pixels sampled, %u refined, %u within the fp32 bound (worst error %.3f of it, largest "
        "bound %.2e m); one cell's sag %.2e m; %u undrawn pixels whose ray meets the water\n",
        drawn, refined, within, worst_ratio, largest_bound, sag, missed);
    // The cameras look at the water: more than half the image is water (a black or empty probe
    // fails).
    EXPECT_GT(drawn, kSamples / 2u);
    EXPECT_EQ(crossings, drawn);
    EXPECT_GE(within, 0.995 * drawn);
}

using water_gpu_refinement = GpuTest;

passes::WaterSurfaceInputs sum_inputs(const std::vector<WaveComponent>& waves, uint32_t grid_resolution) {
    passes::WaterSurfaceInputs inputs;
    inputs.level = 0.0;
    inputs.half_extent = 10.0;
    inputs.grid_resolution = grid_resolution;
    inputs.time = 3.0;
    inputs.waves.model = WaveModel::Sum;
    inputs.waves.components = waves;
    return inputs;
}

void expect_sum_refined(Context& context, const std::vector<WaveComponent>& waves, const glm::dvec3& eye,
                        const glm::dvec3& target, uint32_t screen_cell_pixels = 0) {
    const passes::WaterSurfaceInputs inputs = sum_inputs(waves, 64);
    const auto cpu = std::make_shared<WaveSumSurface>(inputs.waves, inputs.level, inputs.time);
    const CpuSurface surface = [&](double x0, double z0) {
        const SurfacePoint p = cpu->at_parameter(x0, z0);
        return std::pair{p, wave_sum_tolerance(inputs.waves.components, inputs.level, x0, z0, p)};
    };
    double shortest = 1e9, second = 0.0;
    for (const WaveComponent& w : waves) {
        const double k = 2.0 * std::numbers::pi / w.wavelength;
        shortest = std::min(shortest, w.wavelength);
        second += (w.amplitude * k + w.steepness) * k;
    }
    expect_refined_surface(context, inputs, surface,
                           {eye, target, inputs.level, inputs.half_extent, cpu->max_amplitude(), shortest, second, 256,
                            screen_cell_pixels});
}

// The pool's two crossed sines (amplitude 0.017 m, wavelength 0.5 m).
const std::vector<WaveComponent> kSines{{0.017, 0.5, 0.0, 0.0, 0.0, -1.0}, {0.017, 0.5, 90.0, 90.0, 0.0, -1.0}};
// Two Gerstner waves that move points sideways by up to 0.05 m (steepness 0.45 each).
const std::vector<WaveComponent> kGerstner{{0.03, 1.1, 20.0, 0.0, 0.45, -1.0}, {0.02, 0.7, 110.0, 40.0, 0.45, -1.0}};

TEST_F(water_gpu_refinement, SinesFromAbove) {
    expect_sum_refined(context(), kSines, {0.0, 1.2, 4.0}, {0.0, -1.5, -2.0});
}

TEST_F(water_gpu_refinement, SinesFromBelow) {
    expect_sum_refined(context(), kSines, {0.3, -0.8, 3.0}, {0.0, 0.0, -1.0});
}

TEST_F(water_gpu_refinement, GerstnerFromAbove) {
    expect_sum_refined(context(), kGerstner, {0.0, 1.5, 4.0}, {0.0, -1.0, -2.0});
}

TEST_F(water_gpu_refinement, GerstnerFromBelow) {
    expect_sum_refined(context(), kGerstner, {0.3, -0.8, 3.0}, {0.0, 0.0, -1.0});
}

// A choppy 64^2 ocean over a 32 m patch; the water spans one patch, the mesh one cell per node.
struct ChoppyOcean {
    static FftOceanSettings settings() {
        FftOceanSettings ocean;
        ocean.resolution = 64;
        ocean.patch_size = 32.0;
        ocean.wind_speed = 7.0;
        ocean.wind_direction_deg = 25.0;
        ocean.spectrum = OceanSpectrum::Jonswap;
        ocean.fetch = 20000.0;
        ocean.choppiness = 0.8;
        return ocean;
    }
    static constexpr uint64_t kSeed = 77;

    explicit ChoppyOcean(Context& context)
        : ocean(settings()),
          spectrum(std::make_shared<const FftOceanSpectrum>(make_ocean_spectrum(ocean, kSeed))),
          buffer(context, spectrum) {
        inputs.level = 0.0;
        inputs.half_extent = 16.0;
        inputs.grid_resolution = 64;
        inputs.time = 2.0;
        inputs.waves.model = WaveModel::FftOcean;
        inputs.waves.ocean = ocean;
        inputs.waves.seed = kSeed;
        inputs.ocean = &buffer;
    }

    FftOceanSettings ocean;
    std::shared_ptr<const FftOceanSpectrum> spectrum;
    passes::OceanSpectrumBuffer buffer;
    passes::WaterSurfaceInputs inputs;
};

void expect_ocean_refined(Context& context, const glm::dvec3& eye, const glm::dvec3& target,
                          uint32_t screen_cell_pixels = 0) {
    const ChoppyOcean choppy(context);
    const FftOceanSettings& ocean = choppy.ocean;
    const passes::WaterSurfaceInputs& inputs = choppy.inputs;
    const auto& spectrum = choppy.spectrum;
    const OceanReference reference = ocean_reference(*spectrum, ocean.choppiness, inputs.time);
    const CpuSurface surface = [&](double x0, double z0) { return ocean_sample(reference, x0, z0, inputs.level); };
    // The mesh's vertices lie on the FFT's nodes (M = n over one patch), and between them the
    // GPU's surface is the fields' bilinear patch. Either triangle of a cell misses its patch by
    // at most a quarter of the twist |P00 - P10 - P01 + P11| (at the cell's centre): that is the
    // sag, passed to expect_refined_surface as a second derivative that reproduces it.
    const FftOceanGrid& grid = reference.grid;
    auto point = [&](uint32_t x, uint32_t z) {
        const OceanFieldValues& f = grid.values(x % grid.n, z % grid.n);
        return glm::dvec3(f[kOceanDispX], f[kOceanHeight], f[kOceanDispZ]);
    };
    double twist = 0.0;
    for (uint32_t z = 0; z < grid.n; ++z) {
        for (uint32_t x = 0; x < grid.n; ++x) {
            twist = std::max(twist, glm::length(point(x, z) - point(x + 1, z) - point(x, z + 1) + point(x + 1, z + 1)));
        }
    }
    // The CPU's crossing follows the height above (x, z), one value only where the surface does
    // not fold: the horizontal map's Jacobian stays positive at every node.
    double least_jacobian = 1e9;
    for (uint32_t z = 0; z < grid.n; ++z) {
        for (uint32_t x = 0; x < grid.n; ++x) {
            const OceanFieldValues& f = grid.values(x, z);
            least_jacobian = std::min(least_jacobian, (1.0 + f[kOceanDispXdX]) * (1.0 + f[kOceanDispZdZ]) -
                                                          f[kOceanDispXdZ] * f[kOceanDispXdZ]);
        }
    }
    ASSERT_GT(least_jacobian, 0.0);
    const double cell = 2.0 * inputs.half_extent / inputs.grid_resolution;
    const double second = (twist / 4.0) / (2.0 * cell * cell / 8.0);
    const double amplitude = grid.max_abs_height();
    expect_refined_surface(context, inputs, surface,
                           {eye, target, inputs.level, inputs.half_extent, amplitude, 2.0 * grid.spacing(), second,
                            inputs.grid_resolution, screen_cell_pixels});
}

TEST_F(water_gpu_refinement, ChoppyOceanFromAbove) {
    expect_ocean_refined(context(), {0.0, 3.0, 12.0}, {0.0, 0.0, 0.0});
}

TEST_F(water_gpu_refinement, ChoppyOceanFromBelow) {
    expect_ocean_refined(context(), {0.0, -2.0, 10.0}, {0.0, 0.0, 0.0});
}

// The same surfaces drawn from the screen's grid (water.mesh_cell_pixels, 8-pixel cells): the
// pixels whose cells are coarse find their crossing by the march, the rest as above.
constexpr uint32_t kScreenCellPixels = 8;

TEST_F(water_gpu_refinement, SinesFromAboveOnTheScreenGrid) {
    expect_sum_refined(context(), kSines, {0.0, 1.2, 4.0}, {0.0, -1.5, -2.0}, kScreenCellPixels);
}

TEST_F(water_gpu_refinement, SinesFromBelowOnTheScreenGrid) {
    expect_sum_refined(context(), kSines, {0.3, -0.8, 3.0}, {0.0, 0.0, -1.0}, kScreenCellPixels);
}

TEST_F(water_gpu_refinement, GerstnerFromAboveOnTheScreenGrid) {
    expect_sum_refined(context(), kGerstner, {0.0, 1.5, 4.0}, {0.0, -1.0, -2.0}, kScreenCellPixels);
}

TEST_F(water_gpu_refinement, GerstnerFromBelowOnTheScreenGrid) {
    expect_sum_refined(context(), kGerstner, {0.3, -0.8, 3.0}, {0.0, 0.0, -1.0}, kScreenCellPixels);
}

TEST_F(water_gpu_refinement, ChoppyOceanFromAboveOnTheScreenGrid) {
    expect_ocean_refined(context(), {0.0, 3.0, 12.0}, {0.0, 0.0, 0.0}, kScreenCellPixels);
}

TEST_F(water_gpu_refinement, ChoppyOceanFromBelowOnTheScreenGrid) {
    expect_ocean_refined(context(), {0.0, -2.0, 10.0}, {0.0, 0.0, 0.0}, kScreenCellPixels);
}

// Infinite water (docs/model.md section 1, "Infinite water") is drawn from the screen's grid to
// the horizon. On the choppy ocean from 4 m up, over the whole image: every pixel whose ray points
// at least one pixel below the horizon (the ray of the pixel above it points down too) shows
// water; no pixel whose ray rises shows any (the camera is above every crest); and every pixel
// whose ray meets the mean level beyond the far field shows that flat crossing. The far field is
// put at 100 m here (the scenes' is kInfiniteWaterFarField) so that it spans rows of this image.
TEST_F(water_gpu_refinement, InfiniteOceanIsWaterToTheHorizon) {
    const ChoppyOcean choppy(context());
    const double amplitude =
        ocean_reference(*choppy.spectrum, choppy.ocean.choppiness, choppy.inputs.time).grid.max_abs_height();
    Scene scene;
    scene.camera.position = {0.0, 4.0, 20.0};
    scene.camera.target = {0.0, 0.0, -40.0};
    scene.camera.fov_y_deg = 50.0;
    scene.camera.far_plane = 1e5;
    scene.water = Water{};
    scene.water->infinite = true;
    scene.water->half_extent = choppy.inputs.half_extent;
    scene.water->depth = 30.0;
    ASSERT_EQ(scene.water->screen_mesh_cell_pixels(), kScreenCellPixels);
    ASSERT_GT(scene.camera.position.y, amplitude);
    const FrameConstants constants = make_frame_constants(scene, kWidth, kHeight);
    passes::ScreenMesh screen = passes::water_screen_mesh(scene, double(kWidth) / kHeight, amplitude);
    ASSERT_TRUE(screen.infinite);
    constexpr double kFarField = 100.0;
    screen.far_field = static_cast<float>(kFarField);
    const std::vector<glm::vec4> pixels =
        probe_pixels(context(), constants, choppy.inputs, choppy.inputs.grid_resolution, screen);

    const glm::dvec3 eye = scene.camera.position;
    uint32_t below_horizon = 0, far_field = 0;
    for (uint32_t y = 0; y < kHeight; ++y) {
        for (uint32_t x = 0; x < kWidth; ++x) {
            const glm::vec4 gpu = pixels[y * kWidth + x];
            const glm::dvec3 d = pixel_ray(constants, x, y);
            if (d.y > 0.0) {
                EXPECT_EQ(gpu.w, 0.0f) << "pixel (" << x << ", " << y << ") rises but shows water";
                continue;
            }
            if (y > 0 && pixel_ray(constants, x, y - 1).y < 0.0) {
                ++below_horizon;
                EXPECT_NE(gpu.w, 0.0f) << "pixel (" << x << ", " << y << ") lies below the horizon but shows no water";
            }
            // The far field, with 1% of margin for the shader's fp32 decision at its boundary.
            const double to_level = -eye.y / d.y;
            if (to_level * std::hypot(d.x, d.z) > 1.01 * kFarField) {
                ++far_field;
                // Exactly on the level, and on the pixel's ray to 1e-4 rad: the GPU's ray comes
                // from the fp32 inverse of a projection with near 0.05 m and far 1e5 m, which
                // turns it by up to about 1e-5 rad (1.02e-5 measured); a pixel here is 7e-3 rad,
                // so a neighbouring pixel's crossing fails by 70 times the bound.
                EXPECT_EQ(gpu.y, 0.0f) << "pixel (" << x << ", " << y << ")";
                const glm::dvec3 to_shown = glm::normalize(glm::dvec3(gpu) - eye);
                EXPECT_LE(std::acos(std::min(1.0, glm::dot(to_shown, d))), 1e-4) << "pixel (" << x << ", " << y << ")";
            }
        }
    }
    std::printf("%u pixels below the horizon, %u of them in the far field\n", below_horizon, far_field);
    EXPECT_GT(below_horizon, kWidth * kHeight / 3);
    EXPECT_GT(far_field, 2 * kWidth);  // rows of it, not a stray pixel
}

}  // namespace
}  // namespace vkw::test
