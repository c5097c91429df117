#include "passes/water/water_shading.hpp"

#include "engine/framegraph/pass_context.hpp"
#include "engine/scene/effects.hpp"
#include "passes/caustics/caustic_layer.hpp"
#include "passes/common/frame_constants.hpp"
#include "passes/common/frame_keys.hpp"
#include "passes/common/scene_depth.hpp"
#include "passes/receivers/lighting_inputs.hpp"
#include "passes/scene_views/scene_view.hpp"
#include "passes/water/water_surface_draw.hpp"

namespace vkw::passes {

namespace {

uint32_t lookup_code(const std::optional<fg::ImageHandle>& view, SceneLookup method) {
    if (!view) return 0;
    return method == SceneLookup::Projective ? 1 : 2;
}
}  // namespace

WaterSurfaceShading water_surface_shading(const Scene& scene) {
    const WaterShadingSettings& settings = scene.effects.water;
    WaterSurfaceShading shading;
    shading.eye_in_water = camera_eye_in_water(scene);
    shading.fresnel = settings.fresnel;
    shading.fresnel_power = static_cast<float>(settings.fresnel_power);
    shading.glitter = settings.glitter;
    if (settings.depth_blend) {
        shading.depth_blend = true;
        shading.water_colour = glm::vec3(settings.depth_blend->colour);
        shading.blend_k = static_cast<float>(settings.depth_blend->k);
    }
    return shading;
}

void add_water_shading_pass(fg::FrameGraph& graph, const WaterSurfaceBuffers& surface, const WaterSceneLookups& lookups,
                            const WaterSurfaceShading& shading, bool caustic_layer) {
    struct Data {
        WaterSurfaceReads surface;
        fg::ImageHandle hdr, depth;
        LightingInputs lighting;
        // A missing one is stood in for by the other (its lookup is off).
        std::optional<fg::ImageHandle> reflection_view, refraction_view;
        CausticLayerTarget layer;
        std::optional<fg::ImageHandle> refraction_view_caustic;  // read with the layer and the views
        // The refraction view's second layer, and its caustic layer (read with the layer).
        std::optional<fg::ImageHandle> refraction_view_behind, refraction_view_behind_caustic;
    };
    const auto& data = graph.add_pass<Data>(
        "water", fg::PassKind::Graphics,
        [&](fg::PassBuilder& builder, Data& d) {
            builder.serves(Effect::Water);
            d.surface.declare(builder, surface);
            constexpr VkPipelineStageFlags2 fragment = VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT;
            d.hdr = hdr_colour_attachment(builder, graph.blackboard());
            d.depth = scene_depth_attachment(builder, graph.blackboard());
            d.layer.create_or_load(builder, graph.blackboard(), caustic_layer);
            d.lighting.declare(builder, graph.blackboard());
            if (lookups.reflection_view) {
                d.reflection_view =
                    builder.sample("reflection_view", *lookups.reflection_view, fg::Filter::Linear, fragment);
            }
            if (lookups.refraction_view) {
                d.refraction_view =
                    builder.sample("refraction_view", *lookups.refraction_view, fg::Filter::Linear, fragment);
            }
            if (d.layer.image && d.refraction_view && graph.blackboard().has(keys::kRefractionViewCaustic)) {
                d.refraction_view_caustic =
                    builder.sample("refraction_view_caustic", graph.blackboard().get(keys::kRefractionViewCaustic),
                                   fg::Filter::Linear, fragment);
            }
            if (d.refraction_view && lookups.refraction_view_behind) {
                d.refraction_view_behind = builder.sample("refraction_view_behind", *lookups.refraction_view_behind,
                                                          fg::Filter::Linear, fragment);
                if (d.refraction_view_caustic && graph.blackboard().has(keys::kRefractionViewBehindCaustic)) {
                    d.refraction_view_behind_caustic = builder.sample(
                        "refraction_view_behind_caustic", graph.blackboard().get(keys::kRefractionViewBehindCaustic),
                        fg::Filter::Linear, fragment);
                }
            }
        },
        [base = water_surface_push(surface, shading.refine_steps), lookups, shading](const Data& d,
                                                                                     fg::PassContext& context) {
            const bool views = d.reflection_view || d.refraction_view;
            GraphicsPipelineDesc desc;
            desc.vertex_shader = d.surface.vertex_shader();
            desc.fragment_shader = d.lighting.shader("water/water_surface.frag")
                                       .define("VKWATER_SCENE_VIEWS", views)
                                       .define("VKWATER_CAUSTIC_LAYER", d.layer.written())
                                       .file();
            const bool layer_of_views = views && d.layer.written();
            desc.depth_test = true;
            desc.depth_write = true;
            desc.topology = passes::WaterSurfaceReads::kTopology;
            // water_surface.frag's constants 2-5: the Fresnel form, the depth colour, the lookups.
            std::string key = d.surface.specialise(desc, desc.fragment_shader);
            const uint32_t reflection = lookup_code(d.reflection_view, lookups.reflection_method);
            const uint32_t refraction = lookup_code(d.refraction_view, lookups.refraction_method);
            const uint32_t fresnel = static_cast<uint32_t>(shading.fresnel), depth_blend = shading.depth_blend;
            // Constant 6, the camera's side: 0 the air, 1 the water, 2 per pixel (the mask); 7, the glitter.
            const uint32_t side = d.lighting.camera_medium ? 2u : shading.eye_in_water ? 1u : 0u;
            const uint32_t glitter = shading.glitter;
            // Constant 8: 1 where the refracted rays also look in the refraction view's second layer.
            const uint32_t second_layer = d.refraction_view_behind.has_value();
            desc.specialization_constants.insert(
                desc.specialization_constants.end(),
                {fresnel, depth_blend, reflection, refraction, side, glitter, second_layer});
            key += "/fresnel " + std::to_string(fresnel) + "/blend " + std::to_string(depth_blend) + "/lookups " +
                   std::to_string(reflection) + std::to_string(refraction) + "/side " + std::to_string(side) +
                   "/glitter " + std::to_string(glitter) + "/second layer " + std::to_string(second_layer);
            const Pipeline& pipeline = context.pipeline(key, desc);
            std::vector<fg::DescriptorBinding> stand_ins = d.surface.stand_ins(context);
            // A missing view's lookup is off, so the shader never reads it: the other view stands in
            // (likewise for the refraction view's caustic layer).
            if (views) {
                const fg::ImageHandle either = d.reflection_view ? *d.reflection_view : *d.refraction_view;
                if (!d.reflection_view) stand_ins.push_back(context.sampled("reflection_view", either));
                if (!d.refraction_view) stand_ins.push_back(context.sampled("refraction_view", either));
                if (layer_of_views && !d.refraction_view_caustic) {
                    stand_ins.push_back(context.sampled("refraction_view_caustic", either));
                }
                if (!d.refraction_view_behind) stand_ins.push_back(context.sampled("refraction_view_behind", either));
                if (layer_of_views && !d.refraction_view_behind_caustic) {
                    stand_ins.push_back(context.sampled("refraction_view_behind_caustic", either));
                }
            }
            context.bind(pipeline, stand_ins);
            WaterSurfacePush push = base;
            push.reflection_steps = static_cast<uint32_t>(lookups.reflection_steps);
            push.refraction_steps = static_cast<uint32_t>(lookups.refraction_steps);
            push.scene_size = lookups.scene_size;
            push.shallow_blend = lookups.shallow_blend;
            push.fresnel_power = shading.fresnel_power;
            push.blend_k = shading.blend_k;
            push.water_colour[0] = shading.water_colour.r;
            push.water_colour[1] = shading.water_colour.g;
            push.water_colour[2] = shading.water_colour.b;
            d.surface.draw(context, pipeline, push);
        });
    graph.blackboard().put(keys::kHdrColor, data.hdr);
    graph.blackboard().put(keys::kSceneDepth, data.depth);
    data.layer.publish(graph.blackboard());
}

}  // namespace vkw::passes
