#include "passes/frame/renderer.hpp"

#include "engine/core/errors.hpp"
#include "engine/scene/pixel_filter.hpp"
#include "engine/vk/context.hpp"
#include "engine/water/surface.hpp"
#include "passes/caustics/caustic_layer.hpp"
#include "passes/caustics/caustics_blur.hpp"
#include "passes/caustics/caustics_camera_receivers.hpp"
#include "passes/caustics/caustics_camera_splats.hpp"
#include "passes/caustics/caustics_map_frame.hpp"
#include "passes/caustics/caustics_photons.hpp"
#include "passes/caustics/caustics_procedural.hpp"
#include "passes/caustics/caustics_read_region.hpp"
#include "passes/caustics/caustics_resolve.hpp"
#include "passes/common/calibration.hpp"
#include "passes/common/frame_constants_upload.hpp"
#include "passes/common/frame_keys.hpp"
#include "passes/frame/frame_needs.hpp"
#include "passes/frame/temporal_accumulation.hpp"
#include "passes/frame/upscale.hpp"
#include "passes/godrays/godrays.hpp"
#include "passes/godrays/godrays_composite.hpp"
#include "passes/present/readback.hpp"
#include "passes/receivers/floor.hpp"
#include "passes/receivers/receiver_meshes.hpp"
#include "passes/receivers/receivers.hpp"
#include "passes/receivers/sun_shadow.hpp"
#include "passes/scene_views/scene_view.hpp"
#include "passes/sky/sky.hpp"
#include "passes/water/camera_medium.hpp"
#include "passes/water/scene_optics.hpp"
#include "passes/water/water_screen_mesh.hpp"
#include "passes/water/water_shading.hpp"
#include "passes/water/water_surface.hpp"
#include "passes/water/water_surface_spectrum.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <limits>
#include <optional>

namespace vkw {

namespace {
// A layer read back as RGBA32F, as the image's RGB layer `name` (the alpha holds nothing).
ExtraLayer rgb_layer(const std::string& name, const Buffer& readback, size_t pixels) {
    const auto* rgba = static_cast<const float*>(readback.mapped());
    ExtraLayer layer{name, std::vector<float>(pixels * 3)};
    for (size_t i = 0; i < pixels; ++i) {
        for (int c = 0; c < 3; ++c) layer.rgb[3 * i + c] = rgba[4 * i + c];
    }
    return layer;
}

// Texels per side of the light-space caustic map: matched to the photon grid (R photons
// per side, plus the fit's one-texel border), so that each texel receives about one
// photon on flat water and the 2x2 splat kernel leaves no holes between photons (the
// photon-density sizing of the splat, de la Fuente 2011's point size regulation, comes later).
// The caustic map's texels per side: map_scale texels per water cell, plus a texel of border on
// each side (scale 1: texel = cell, passes/caustics/caustics_light_space.hpp).
uint32_t caustic_map_texels(uint32_t grid_resolution, double map_scale) {
    const auto texels = static_cast<uint32_t>(std::lround(grid_resolution * map_scale));
    return std::clamp(texels + 2, 16u, 16384u);
}

VkDeviceSize hdr_bytes(uint32_t width, uint32_t height) { return VkDeviceSize{width} * height * 4 * sizeof(float); }

// The sun's direction under the flat surface (Snell; the sun is above the horizon, so it
// always enters).
glm::dvec3 refracted_sun(const Scene& scene) {
    const glm::dvec3 s = scene.sun.direction;
    const double eta = 1.0 / scene.water->ior;
    const double cos_i = -s.y;
    const double cos_t = std::sqrt(1.0 - eta * eta * (1.0 - cos_i * cos_i));
    return glm::normalize(eta * s + (eta * cos_i - cos_t) * glm::dvec3(0.0, 1.0, 0.0));
}

// The views' clip planes (the scene views, the camera-space caustics' receivers): the waves'
// amplitude and a millimetre beyond the mean level.
float scene_view_clip_margin(double amplitude) { return static_cast<float>(amplitude + 1e-3); }

bool casts_sun_shadows(const Scene& scene, const passes::ReceiverMeshes* receivers) {
    return receivers && !receivers->empty() && scene.sun.direction.y < 0.0;
}
// The scene views the water's reflected and refracted rays look the receiver meshes up in
// (passes/scene_views/scene_view.hpp), as the frame's needs and the scene's methods ask.
passes::WaterSceneLookups scene_lookups(fg::FrameGraph& graph, const Scene& scene,
                                        const passes::ReceiverMeshes* receivers, bool caustic_layer, double amplitude) {
    passes::WaterSceneLookups lookups;
    if (!receivers || receivers->empty()) return lookups;
    const EffectSettings& reflection = scene.effects[Effect::Reflection];
    const EffectSettings& refraction = scene.effects[Effect::Refraction];
    const float clip_margin = scene_view_clip_margin(amplitude);
    if (graph.needs().needs(Effect::Reflection)) {
        const bool mirrored = reflection.method == SceneLookup::Projective;
        lookups.reflection_view = passes::add_scene_view_pass(
            graph, *receivers,
            {mirrored ? "mirrored reflection view" : "reflection view", mirrored, true, clip_margin});
    }
    if (graph.needs().needs(Effect::Refraction)) {
        lookups.refraction_view = passes::add_scene_view_pass(
            graph, *receivers, {"refraction view", false, false, clip_margin, caustic_layer});
        if (graph.needs().needs(Effect::RefractionSecondLayer)) {
            lookups.refraction_view_behind = passes::add_scene_view_pass(
                graph, *receivers,
                {"refraction view second layer", false, false, clip_margin, caustic_layer, lookups.refraction_view});
        }
    }
    lookups.reflection_method = reflection.method;
    lookups.refraction_method = refraction.method;
    lookups.reflection_steps = reflection.max_steps;
    lookups.refraction_steps = refraction.max_steps;
    lookups.shallow_blend = static_cast<float>(refraction.shallow_blend);
    // A march with no floor to end it looks as far as across the scene's squares twice.
    lookups.scene_size = static_cast<float>(4.0 * std::max(scene.floor.half_extent, scene.water->half_extent));
    return lookups;
}

// The map a later sub-frame reads instead of making it (CausticMapCarry::Reuse): the kept image
// and this frame's light space (the same as the first sub-frame's, as the sun and the waves are).
std::optional<passes::CausticMap> reused_caustic_map(fg::FrameGraph& graph, const passes::CausticInputs& caustics,
                                                     const CausticMapCarrying* carry) {
    if (!carry || carry->mode != CausticMapCarry::Reuse) return std::nullopt;
    const fg::ImportedImage kept = carry->kept(passes::caustic_map_image(passes::fit_caustic_map(caustics)));
    if (kept.image == VK_NULL_HANDLE) return std::nullopt;
    return passes::CausticMap{passes::import_kept_caustic_map(graph, kept),
                              passes::add_caustic_map_frame_pass(graph, caustics)};
}

}  // namespace

passes::CausticReadInputs caustic_read_inputs(const Scene& scene, double aspect, const fg::FrameNeeds& needs,
                                              double amplitude, double lowest_receiver) {
    const Water& water = *scene.water;
    passes::CausticReadInputs in;
    in.view_proj = projection_matrix(scene.camera, aspect) * view_matrix(scene.camera);
    in.level = water.level;
    in.half_extent = water.half_extent;
    in.amplitude = amplitude;
    // The FFT ocean's fields have no slope bound (a CPU surface would cost its FFTs to build).
    in.max_slope = frame_shape_bounds(water.waves, water.level, water.time).slope;
    in.ior = water.ior;
    in.lowest_receiver = lowest_receiver;
    in.camera_may_be_in_water = needs.needs(Effect::UnderwaterView);
    in.camera_space_splats = scene.effects.caustics.splat == CausticSplat::CameraSpace;
    // A read samples its texel and a neighbour (bilinear); the blur spreads each texel over a
    // tent of at most 1 + 4 texels (passes/caustics/caustics_blur.hpp).
    in.read_margin = needs.needs(Effect::CausticBlur) ? 6 : 1;
    return in;
}

void build_frame_graph(fg::FrameGraph& graph, const Scene& scene, const FrameConstants* constants, uint32_t width,
                       uint32_t height, VkBuffer readback, const passes::OceanSpectrumBuffer* ocean,
                       const passes::ReceiverMeshes* receivers, const FrameOutput* output, LayerReadbacks layers,
                       passes::CausticReadRegionCache* read_regions, VkExtent2D output_size,
                       const CausticMapCarrying* carry, const passes::TemporalInputs* temporal) {
    const bool caustic_layer = output ? output->caustic_layer : layers.caustic != VK_NULL_HANDLE;
    const bool inscatter_layer = layers.inscatter != VK_NULL_HANDLE && !output;
    // The waves' amplitude bound, once: for the FFT ocean it builds the CPU surface.
    const double amplitude = scene.water ? water_bounds(scene).hi.y - scene.water->level : 0.0;
    passes::add_frame_constants_upload(graph, constants);
    passes::add_scene_optics_pass(graph);
    // The sun shadow map first: the caustic photons are traced against it.
    std::optional<passes::SunShadowMap> sun_shadow;
    if (casts_sun_shadows(scene, receivers)) {
        // Everything that can receive the sun above the water: the meshes and the floor square.
        passes::SunShadowInputs shadow;
        shadow.sun_direction = scene.sun.direction;
        const double e = scene.floor.half_extent;
        shadow.bounds_lo = glm::min(receivers->bounds_lo(), glm::dvec3(-e, scene.floor.height, -e));
        shadow.bounds_hi = glm::max(receivers->bounds_hi(), glm::dvec3(e, scene.floor.height, e));
        shadow.size = scene.sun.shadow_texels;
        if (scene.water) shadow.beam = passes::UnderwaterBeam{refracted_sun(scene), scene.water->level};
        sun_shadow = passes::add_sun_shadow_pass(graph, *receivers, shadow);
        graph.blackboard().put(keys::kSunShadow, *sun_shadow);
    }
    // The surface first: the camera-medium split, which the floor reads, evaluates it.
    std::optional<passes::WaterSurfaceBuffers> water_buffers;
    std::optional<fg::BufferHandle> surface;  // the grid
    if (scene.water && graph.needs().needs(Effect::Water)) {
        const Water& water = *scene.water;
        passes::WaterSurfaceInputs inputs{water.level, water.half_extent, water.grid_resolution,
                                          water.time,  water.waves,       ocean};
        const passes::ScreenMesh screen = passes::water_screen_mesh(scene, double(width) / double(height), amplitude);
        water_buffers = passes::add_water_surface_passes(graph, inputs, water.drawn_mesh_resolution(), screen);
        surface = water_buffers->grid;
        // Without it (culled: no ray can start in the water) the shading falls back to the
        // per-frame camera medium of the frame constants.
        if (graph.needs().needs(Effect::UnderwaterView)) {
            passes::add_camera_medium_pass(graph, *water_buffers, water_bottom(scene), amplitude);
        }
        if (graph.needs().needs(Effect::SurfaceCaustics)) {
            // The sun under the water becomes the caustic map; the flat stand-in goes.
            passes::CausticInputs caustics;
            caustics.surface = *surface;
            caustics.grid_resolution = water.grid_resolution;
            caustics.water_level = water.level;
            caustics.half_extent = water.half_extent;
            caustics.max_amplitude = amplitude;
            caustics.sun_direction = scene.sun.direction;
            caustics.sun_irradiance = scene.sun.irradiance;
            caustics.ior = water.ior;
            caustics.sigma_t = scene.medium.sigma_t();
            caustics.floor_height = scene.floor.height;
            caustics.sub_photons = scene.effects.caustics.sub_photons;
            caustics.jitter = scene.effects.caustics.jitter;
            caustics.kernel = scene.effects.caustics.kernel;
            caustics.map_width = caustics.map_height =
                caustic_map_texels(water.grid_resolution, scene.effects.caustics.map_scale);
            if (scene.effects.caustics.splat == CausticSplat::CameraSpace) {
                // The photons onto the receivers the camera sees (the light-space map and its blur
                // are left out: nothing reads them).
                const passes::CameraCausticExtent extent = passes::camera_caustic_extent(width, height);
                const fg::ImageHandle view =
                    passes::add_caustic_receivers_pass(graph, receivers, extent, scene_view_clip_margin(amplitude));
                graph.blackboard().put(keys::kCameraCaustics,
                                       passes::add_caustic_camera_splat_passes(graph, caustics, view, extent,
                                                                               sun_shadow ? &*sun_shadow : nullptr));
            } else if (const std::optional<passes::CausticMap> kept = reused_caustic_map(graph, caustics, carry)) {
                graph.blackboard().put(keys::kCausticMap, *kept);
            } else {
                if (scene.effects.caustics.cull) {
                    const double lowest = receivers && !receivers->empty()
                                              ? std::min(scene.floor.height, receivers->bounds_lo().y)
                                              : scene.floor.height;
                    const passes::CausticMapFrame map = passes::fit_caustic_map(caustics);
                    passes::CausticReadInputs read =
                        caustic_read_inputs(scene, double(width) / double(height), graph.needs(), amplitude, lowest);
                    if (carry && carry->mode == CausticMapCarry::Keep) read.more_views = carry->more_views;
                    passes::CausticReadRegionCache one_frame;  // without the caller's: this frame's alone
                    const passes::CausticReadRegion& region =
                        (read_regions ? *read_regions : one_frame).region(map, read);
                    if (region.bounded) {
                        caustics.read_texels = passes::CausticReadTexels{
                            {region.x0, region.y0, region.x1, region.y1}, region.packed_rows, region.photon_spread};
                        // The blur reads around every texel it writes, so with it the map stays whole.
                        caustics.hold_read_texels_only = !graph.needs().needs(Effect::CausticBlur);
                    }
                    caustics.read_note = region.note;
                } else {
                    caustics.read_note = "every photon kept: effects.caustics.cull is false";
                }
                passes::CausticMap map =
                    scene.effects.caustics.method == CausticMethod::Procedural
                        ? passes::add_caustic_procedural_pass(graph, caustics)
                        : passes::add_caustic_resolve_pass(
                              graph,
                              passes::add_caustic_photon_pass(graph, caustics, sun_shadow ? &*sun_shadow : nullptr),
                              caustics);
                if (graph.needs().needs(Effect::CausticBlur)) {
                    map = passes::add_caustic_blur_pass(graph, map, caustics, scene.effects.caustic_blur.radius);
                }
                if (carry && carry->mode == CausticMapCarry::Keep) {
                    passes::add_caustic_map_keep_pass(
                        graph, map.irradiance,
                        carry->kept(passes::caustic_map_image(passes::fit_caustic_map(caustics))));
                }
                graph.blackboard().put(keys::kCausticMap, map);
            }
        }
    }
    // The water before the floor and the receiver meshes: none of them blends, so the depth test
    // alone decides each pixel, and the floor's pixels behind the surface (all of pool's) fail it
    // before their fragments are shaded.
    if (surface) {
        passes::add_water_shading_pass(graph, *water_buffers,
                                       scene_lookups(graph, scene, receivers, caustic_layer, amplitude),
                                       passes::water_surface_shading(scene), caustic_layer);
    }
    passes::add_floor_pass(graph, caustic_layer);
    if (receivers && !receivers->empty()) passes::add_receivers_pass(graph, *receivers);
    // The sky last of the opaque passes, over only the pixels they left (so none is shaded twice),
    // and after the camera-medium split: a ray from the water that meets nothing sees nothing, or
    // under infinite water the in-scatter of its run to the bottom.
    passes::add_sky_pass(graph, scene.water && scene.water->infinite);
    // Godrays only with a decision, as the frame constants' analytic in-scatter switch has it.
    const fg::EffectDecision* godrays = graph.needs().find(Effect::VolumeCaustics);
    if (surface && godrays && godrays->needed) {
        passes::add_godray_passes(graph, {*surface, scene.water->grid_resolution, amplitude, scene.effects.godrays,
                                          width, height, inscatter_layer});
    }
    if (output_size.width == 0) output_size = {width, height};
    if (output_size.width != width || output_size.height != height) {
        // The resolution scale: every image the frame hands on, stretched to the output size.
        fg::Blackboard& board = graph.blackboard();
        board.put(keys::kHdrColor, passes::add_upscale_pass(graph, board.get(keys::kHdrColor), output_size.width,
                                                            output_size.height, "upscale"));
        if (caustic_layer) {
            board.put(keys::kCausticLayer,
                      passes::add_upscale_pass(graph, board.get(keys::kCausticLayer), output_size.width,
                                               output_size.height, "caustic layer upscale"));
        }
        if (inscatter_layer && board.has(keys::kInScatterLayer)) {
            board.put(keys::kInScatterLayer,
                      passes::add_upscale_pass(graph, board.get(keys::kInScatterLayer), output_size.width,
                                               output_size.height, "in-scatter layer upscale"));
        }
    }
    if (temporal) {
        fg::Blackboard& board = graph.blackboard();
        board.put(keys::kHdrColor, passes::add_temporal_accumulation(graph, board.get(keys::kHdrColor), *temporal));
    }
    if (output) {
        output->add_passes(graph, graph.blackboard().get(keys::kHdrColor));
        return;
    }
    const VkDeviceSize bytes = hdr_bytes(output_size.width, output_size.height);
    passes::add_readback_pass(graph, graph.blackboard().get(keys::kHdrColor), readback, bytes);
    if (caustic_layer) {
        passes::add_readback_pass(graph, graph.blackboard().get(keys::kCausticLayer), layers.caustic, bytes,
                                  "caustic layer readback");
    }
    if (inscatter_layer && graph.blackboard().has(keys::kInScatterLayer)) {
        passes::add_readback_pass(graph, graph.blackboard().get(keys::kInScatterLayer), layers.inscatter, bytes,
                                  "in-scatter layer readback");
    }
}

// The frame's readback targets, kept while the output size and layers stay the same (the graph
// imports them, so they outlive every graph that does).
struct Renderer::Readback {
    uint32_t width = 0, height = 0;
    bool with_hdr = false;  // false for a window's frame, which ends in its own hand-off
    bool caustic_layer = false, inscatter_layer = false;
    Buffer hdr;
    Buffer caustic;    // RenderOptions::caustic_layer only
    Buffer inscatter;  // RenderOptions::inscatter_layer only
};

// This frame's declaration and the executor whose resources run it: the executor outlives the
// graphs it adopts, one per frame, while their physical signature holds.
struct Renderer::CompiledFrame {
    std::unique_ptr<fg::FrameGraph> graph;
    std::unique_ptr<fg::FrameExecutor> executor;
    fg::ExecutorOptions options;
};

const passes::OceanSpectrumBuffer* Renderer::ocean_spectrum(const Scene& scene) {
    std::shared_ptr<const passes::OceanSpectrumBuffer> ocean = uploads_->ocean_spectrum(scene);
    if (ocean != ocean_) {
        forget_compiled_frames();  // they imported the old buffer
        ocean_ = std::move(ocean);
    }
    return ocean_.get();
}

const passes::ReceiverMeshes* Renderer::receiver_meshes(const Scene& scene) {
    std::shared_ptr<const passes::ReceiverMeshes> receivers = uploads_->receiver_meshes(scene);
    if (receivers != receivers_) {
        forget_compiled_frames();  // they imported the old buffers
        receivers_ = std::move(receivers);
    }
    return receivers_.get();
}

fg::ImportedImage Renderer::kept_caustic_map(const fg::ImageInfo& info, CausticMapCarry mode) {
    const bool fits = kept_caustic_map_ && kept_caustic_map_->desc().width == info.width &&
                      kept_caustic_map_->desc().height == info.height &&
                      kept_caustic_map_->desc().format == info.format;
    if (!fits) {
        if (mode != CausticMapCarry::Keep) return {};
        forget_compiled_frames();  // one may import the old image
        kept_caustic_map_ = std::make_unique<Image>(
            context_, ImageDesc{info.width, info.height, info.format, passes::kKeptCausticMapUsage},
            "kept caustic irradiance");
    }
    fg::ImportedImage kept;
    kept.image = kept_caustic_map_->handle();
    kept.view = kept_caustic_map_->view();
    kept.width = info.width;
    kept.height = info.height;
    kept.format = info.format;
    return kept;
}

const Renderer::Readback& Renderer::readback_targets(const RenderOptions& options, bool window_output) {
    // A window's frame ends in its own hand-off (FrameOutput), not in a readback: no buffers.
    const bool hdr = !window_output;
    const bool caustic = hdr && options.caustic_layer;
    const bool inscatter = hdr && options.inscatter_layer;
    if (readback_ && readback_->width == options.width && readback_->height == options.height &&
        readback_->with_hdr == hdr && readback_->caustic_layer == caustic && readback_->inscatter_layer == inscatter) {
        return *readback_;
    }
    forget_compiled_frames();  // they imported the old buffers
    readback_ = std::make_unique<Readback>();
    *readback_ = {options.width, options.height, hdr, caustic, inscatter, {}, {}, {}};
    if (hdr) {
        const BufferDesc desc{hdr_bytes(options.width, options.height), VK_BUFFER_USAGE_TRANSFER_DST_BIT, true};
        readback_->hdr = Buffer(context_, desc, "HDR readback");
        if (caustic) readback_->caustic = Buffer(context_, desc, "caustic layer readback");
        if (inscatter) readback_->inscatter = Buffer(context_, desc, "in-scatter layer readback");
    }
    return *readback_;
}

void Renderer::forget_compiled_frames() {
    for (std::unique_ptr<CompiledFrame>& frame : compiled_) frame.reset();
}

Renderer::Renderer(Context& context, std::shared_ptr<fg::PipelineStore> pipelines,
                   std::shared_ptr<SceneUploads> uploads)
    : context_(context),
      pipelines_(pipelines ? std::move(pipelines) : std::make_shared<fg::PipelineStore>()),
      uploads_(uploads ? std::move(uploads) : std::make_shared<SceneUploads>(context)),
      constants_(std::make_unique<FrameConstants>()) {}

Renderer::~Renderer() = default;

RenderResult Renderer::render(const Scene& scene, const RenderOptions& options) {
    CompiledFrame& frame = prepare(scene, options, nullptr);
    RenderResult result;
    result.timing = frame.executor->execute();
    result.image.width = static_cast<int>(options.width);
    result.image.height = static_cast<int>(options.height);
    result.image.rgba.resize(size_t{options.width} * options.height * 4);
    std::memcpy(result.image.rgba.data(), readback_->hdr.mapped(), result.image.rgba.size() * sizeof(float));
    const size_t pixels = size_t{options.width} * options.height;
    if (options.caustic_layer) result.image.layers.push_back(rgb_layer("caustic", readback_->caustic, pixels));
    if (options.inscatter_layer && frame.graph->blackboard().has(keys::kInScatterLayer)) {
        result.image.layers.push_back(rgb_layer("inscatter", readback_->inscatter, pixels));
    }
    return result;
}

fg::FrameExecutor& Renderer::prepare_frame(const Scene& scene, const RenderOptions& options,
                                           const FrameOutput& output) {
    return *prepare(scene, options, &output).executor;
}

void Renderer::reload_shaders() {
    vkDeviceWaitIdle(context_.device());
    forget_compiled_frames();
    *pipelines_ = fg::PipelineStore{};  // shared: the other renderers must reload too (the window has one)
}

glm::dvec2 Renderer::next_temporal_shift(uint32_t width, uint32_t height) const {
    // A history of another size is made anew: its first frame is frame 0 of the cycle.
    const Image* history = temporal_.history.get();
    const bool fits = history && history->desc().width == width && history->desc().height == height;
    return image_shift_for_pixel_offset(passes::temporal_jitter(fits ? temporal_.frames : 0), width, height);
}

fg::ImportedImage Renderer::temporal_history(uint32_t width, uint32_t height) {
    Image* history = temporal_.history.get();
    if (!history || history->desc().width != width || history->desc().height != height) {
        forget_compiled_frames();  // one may import the old image
        temporal_.history = std::make_unique<Image>(
            context_, ImageDesc{width, height, VK_FORMAT_R32G32B32A32_SFLOAT, passes::kTemporalHistoryUsage},
            "temporal history");
        temporal_.frames = 0;  // a new image holds nothing yet
    }
    fg::ImportedImage imported;
    imported.image = temporal_.history->handle();
    imported.view = temporal_.history->view();
    imported.width = width;
    imported.height = height;
    imported.format = VK_FORMAT_R32G32B32A32_SFLOAT;
    return imported;
}

Renderer::CompiledFrame& Renderer::prepare(const Scene& scene, const RenderOptions& options,
                                           const FrameOutput* output) {
    const uint32_t max_size = context_.properties().limits.maxImageDimension2D;
    if (options.width == 0 || options.height == 0 || options.width > max_size || options.height > max_size) {
        throw UserError("--width/--height: " + std::to_string(options.width) + "x" + std::to_string(options.height) +
                        " is out of range (accepted: 1 to " + std::to_string(max_size) + " on '" +
                        context_.device_name() + "')");
    }
    if (!options.temporal.enabled) {
        temporal_.frames = 0;
        return prepare_graph(scene, options, output, nullptr);
    }
    const double floor = options.temporal.blend_floor;
    if (!(floor > 0.0 && floor <= 1.0) && !(floor == 0.0 && !options.temporal.clamp_history)) {
        throw InternalError("temporal accumulation: blend_floor " + std::to_string(floor) + " is outside (0, 1]");
    }
    // The caller shifted the camera by this frame's jitter, as for the sub-frames of a box filter
    // (the scene is not copied: its receivers are large, and their uploads are keyed on it).
    const glm::dvec2 jitter = next_temporal_shift(options.width, options.height);
    if (scene.camera.image_shift_ndc != jitter) {
        throw InternalError(
            "temporal accumulation: the camera's image shift is not this frame's jitter "
            "(set it to Renderer::next_temporal_shift before the frame)");
    }
    passes::TemporalInputs inputs;
    inputs.history = temporal_history(options.width, options.height);
    // The reprojection is between unjittered cameras.
    Camera unjittered = scene.camera;
    unjittered.image_shift_ndc = glm::dvec2(0.0);
    const glm::dmat4 view_proj =
        projection_matrix(unjittered, double(options.width) / double(options.height)) * view_matrix(unjittered);
    inputs.first = temporal_.frames == 0;
    inputs.reprojection = glm::mat4(passes::temporal_reprojection(temporal_.previous_view_proj, view_proj));
    // Exactly the same camera: the reprojection is the identity, which fp32 would only round to one.
    inputs.camera_still = view_proj == temporal_.previous_view_proj;
    inputs.blend = static_cast<float>(std::max(1.0 / (temporal_.frames + 1.0), floor));
    inputs.clamp_history = options.temporal.clamp_history;
    CompiledFrame& frame = prepare_graph(scene, options, output, &inputs);
    temporal_.previous_view_proj = view_proj;
    ++temporal_.frames;
    return frame;
}

Renderer::CompiledFrame& Renderer::prepare_graph(const Scene& scene, const RenderOptions& options,
                                                 const FrameOutput* output, const passes::TemporalInputs* temporal) {
    if (scene.water) {
        // The surface grid must fit the device: a quarter of its largest heap at most, so
        // the frame's other targets fit beside it, and one storage-buffer binding (the water
        // and stencil passes pull every vertex through one).
        VkPhysicalDeviceMemoryProperties memory;
        vkGetPhysicalDeviceMemoryProperties(context_.physical_device(), &memory);
        VkDeviceSize largest_heap = 0;
        for (uint32_t i = 0; i < memory.memoryHeapCount; ++i)
            largest_heap = std::max(largest_heap, memory.memoryHeaps[i].size);
        const VkDeviceSize limit =
            std::min<VkDeviceSize>(largest_heap / 4, context_.properties().limits.maxStorageBufferRange);
        uint32_t largest_grid = 1;
        while (passes::water_surface_bytes(largest_grid * 2) <= limit) largest_grid *= 2;
        if (passes::water_surface_bytes(scene.water->grid_resolution) > limit) {
            throw UserError(scene.source.string() +
                            ": water.grid_resolution: " + std::to_string(scene.water->grid_resolution) + " needs " +
                            std::to_string(passes::water_surface_bytes(scene.water->grid_resolution) >> 20) +
                            " MiB of surface vertices (accepted on '" + context_.device_name() + "': up to about " +
                            std::to_string(largest_grid) + ")");
        }
    }
    if (!(options.render_scale > 0.0 && options.render_scale <= 1.0)) {
        throw UserError("--render-scale: " + std::to_string(options.render_scale) +
                        " is out of range (accepted: 0 < value <= 1)");
    }
    // The size the scene's passes render at (the frame is stretched to the options' size at its end).
    const uint32_t width = passes::scaled_size(options.width, options.render_scale);
    const uint32_t height = passes::scaled_size(options.height, options.render_scale);
    if (scene.water && scene.effects.caustics.splat == CausticSplat::CameraSpace) {
        // The camera-space splats' flux buffer is one storage binding.
        const passes::CameraCausticExtent extent = passes::camera_caustic_extent(width, height);
        const VkDeviceSize range = context_.properties().limits.maxStorageBufferRange;
        const double bytes_per_pixel = double(passes::camera_caustic_flux_bytes(extent)) / (double(width) * height);
        if (passes::camera_caustic_flux_bytes(extent) > range) {
            throw UserError(scene.source.string() + ": effects.caustics.splat: camera-space splats at " +
                            std::to_string(width) + "x" + std::to_string(height) + " need " +
                            std::to_string(passes::camera_caustic_flux_bytes(extent) >> 20) +
                            " MiB of flux in one storage binding (accepted on '" + context_.device_name() +
                            "': up to " + std::to_string(range >> 20) + " MiB, about " +
                            std::to_string(static_cast<uint64_t>(double(range) / bytes_per_pixel / 1e3)) +
                            " thousand output pixels; or splat light-space)");
        }
    }
    // The CPU's share of the frame, timed from the needs' decision to the compiled graph: the
    // decision runs every frame too (it reads the camera and the waves' bounds).
    const auto declare_start = std::chrono::steady_clock::now();
    // The graph is declared and compiled every frame (what its passes capture, the clock and
    // every setting, is new each frame), in the storage of the graph before the last; the device
    // objects are made only when the compiled graph's physical signature changes.
    std::unique_ptr<fg::FrameGraph> graph = std::move(spare_graph_);
    if (graph) {
        graph->clear();
    } else {
        graph = std::make_unique<fg::FrameGraph>();
    }
    decide_frame_needs(scene, double(width) / double(height), graph->needs_to_decide());
    const fg::FrameNeeds& needs = graph->needs();
    *constants_ = make_frame_constants(scene, width, height);
    // Counted once (docs/model.md section 1): the godray passes, when they run, are the
    // in-scatter of sunlight, and the shading's analytic in-scatter is switched off. (An
    // effect without a decision counts as needed; godrays have passes only once decided.)
    const fg::EffectDecision* godrays = needs.find(Effect::VolumeCaustics);
    if (godrays && godrays->needed) constants_->medium_options.x = 0.0f;
    const passes::OceanSpectrumBuffer* ocean = ocean_spectrum(scene);
    const passes::ReceiverMeshes* receivers = receiver_meshes(scene);
    const Readback& readback = readback_targets(options, output != nullptr);

    graph->set_default_recording(options.recording);
    CausticMapCarrying carry;
    carry.mode = options.caustic_map_carry;
    carry.kept = [this, mode = carry.mode](const fg::ImageInfo& info) { return kept_caustic_map(info, mode); };
    if (carry.mode == CausticMapCarry::Keep) {
        Camera camera = scene.camera;
        for (const glm::dvec2& shift : options.sub_frame_shifts) {
            if (shift == scene.camera.image_shift_ndc) continue;
            camera.image_shift_ndc = shift;
            carry.more_views.push_back(projection_matrix(camera, double(width) / double(height)) * view_matrix(camera));
        }
    }
    build_frame_graph(*graph, scene, constants_.get(), width, height, readback.hdr.handle(), ocean, receivers, output,
                      {readback.caustic.handle(), readback.inscatter.handle()}, &read_regions_,
                      {options.width, options.height}, &carry, temporal);
    // Timed frames carry the unit their times are reported in; untimed ones (tests) need none.
    if (options.timing != fg::TimingMode::None) passes::add_calibration_pass(*graph);
    // A supersampled frame's first sub-frame and its later ones compile to two graphs: each keeps
    // its own device objects, so that alternating between them makes none.
    std::unique_ptr<CompiledFrame>& compiled = compiled_[static_cast<size_t>(options.caustic_map_carry)];
    graph->compile(width, height, compiled ? compiled->graph.get() : nullptr);
    if (graph->took_over_compilation()) ++compilations_taken_over_;
    const fg::ExecutorOptions executor_options{options.check_finite, options.timing};
    const bool reuse = compiled && compiled->executor->can_adopt(*graph, executor_options);
    last_declare_ms_ =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - declare_start).count();
    if (reuse) {
        compiled->executor->adopt(*graph);
        // The previous frame's declaration goes (its storage stays for the next); its objects stay.
        std::swap(compiled->graph, graph);
        graph->clear();  // what its passes captured goes now, as when it was destroyed
        spare_graph_ = std::move(graph);
        return *compiled;
    }
    compiled.reset();  // release the old graph's resources before making new ones
    auto frame = std::make_unique<CompiledFrame>();
    frame->graph = std::move(graph);
    frame->options = executor_options;
    frame->executor = std::make_unique<fg::FrameExecutor>(context_, *frame->graph, *pipelines_, executor_options);
    ++realize_count_;
    compiled = std::move(frame);
    return *compiled;
}

}  // namespace vkw
