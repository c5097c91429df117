// add_sun_shadow_pass and its light-space fit (sun_shadow.hpp).
#include "passes/receivers/sun_shadow.hpp"

#include "engine/core/errors.hpp"
#include "engine/framegraph/pass_context.hpp"
#include "engine/vk/shader_variant.hpp"
#include "passes/caustics/caustics_light_space.hpp"
#include "passes/receivers/receiver_draws.hpp"

#include <shader_structs/receivers/sun_shadow.frag.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace vkw::passes {

ShadowProjection fit_shadow_projection(const glm::dvec3& direction, const glm::dvec3& bounds_lo,
                                       const glm::dvec3& bounds_hi, uint32_t size) {
    bool finite = true;
    for (int k = 0; k < 3; ++k) finite = finite && std::isfinite(bounds_lo[k]) && std::isfinite(bounds_hi[k]);
    if (std::abs(glm::length(direction) - 1.0) >= 1e-9 || !finite || glm::any(glm::lessThan(bounds_hi, bounds_lo)) ||
        size < 1 || size > 16384) {
        throw InternalError(
            "sun shadow: inputs out of range (accepted: a unit direction, a finite box with "
            "lo <= hi, 1 <= size <= 16384); got size " +
            std::to_string(size));
    }
    const glm::dvec3 s = direction;
    glm::dvec3 u, v;
    branchless_basis(s, u, v);
    // The box's corners in light space: (u, v) across the map, d = s.P along the beam.
    glm::dvec3 lo(std::numeric_limits<double>::max()), hi(-std::numeric_limits<double>::max());
    for (int corner = 0; corner < 8; ++corner) {
        const glm::dvec3 p((corner & 1) ? bounds_hi.x : bounds_lo.x, (corner & 2) ? bounds_hi.y : bounds_lo.y,
                           (corner & 4) ? bounds_hi.z : bounds_lo.z);
        const glm::dvec3 q(glm::dot(p, u), glm::dot(p, v), glm::dot(p, s));
        lo = glm::min(lo, q);
        hi = glm::max(hi, q);
    }
    // A margin of 1% (at least 1 cm) keeps every covered point strictly inside the map and the
    // depth range, so no occluder is clipped at the near or far plane.
    const glm::dvec3 margin = glm::max(0.01 * (hi - lo), glm::dvec3(0.01));
    lo -= margin;
    hi += margin;
    const glm::dvec3 extent = hi - lo;
    // Rows of the orthographic projection: x, y = 2 (q - lo) / extent - 1, z = (hi_d - d) / extent_d.
    const glm::dvec4 row_x(2.0 * u / extent.x, -(hi.x + lo.x) / extent.x);
    const glm::dvec4 row_y(2.0 * v / extent.y, -(hi.y + lo.y) / extent.y);
    const glm::dvec4 row_z(-s / extent.z, hi.z / extent.z);
    ShadowProjection projection{};
    for (int col = 0; col < 4; ++col) {
        projection.light_from_world[col] =
            glm::vec4(float(row_x[col]), float(row_y[col]), float(row_z[col]), col == 3 ? 1.0f : 0.0f);
    }
    projection.params = glm::vec4(float(std::max(extent.x, extent.y) / size), float(extent.z), float(size), 1.0f);
    return projection;
}

SunShadowSpace fit_sun_shadow(const SunShadowInputs& in) {
    SunShadowSpace space{};
    space.sun = fit_shadow_projection(in.sun_direction, in.bounds_lo, in.bounds_hi, in.size);
    if (in.beam) {
        // Only what lies under the water casts along the beam; the box above it is cut off.
        glm::dvec3 hi = in.bounds_hi;
        hi.y = std::max(std::min(hi.y, in.beam->water_level), in.bounds_lo.y);
        space.beam = fit_shadow_projection(in.beam->direction, in.bounds_lo, hi, in.size);
    }
    return space;
}

namespace {
// The push block of receivers/sun_shadow.vert and .frag, generated from the cutout fragment variant
// (the one that declares all of it; tools/shader_structs): light_from_world; clip.x, meshes above
// this height cast nothing in this half; material.x the base colour factor's alpha, material.y a
// cutout's threshold (negative: opaque).
using ShadowPush = glsl::sun_shadow_frag::SunShadowPush;
}  // namespace

SunShadowMap add_sun_shadow_pass(fg::FrameGraph& graph, const ReceiverMeshes& meshes, const SunShadowInputs& inputs) {
    const SunShadowSpace space = fit_sun_shadow(inputs);

    struct Upload {
        fg::BufferHandle space;
    };
    const auto& upload = graph.add_pass<Upload>(
        "sun shadow space", fg::PassKind::Transfer,
        [&](fg::PassBuilder& builder, Upload& d) {
            d.space = builder.copy_destination(builder.create_buffer("sun shadow space", {sizeof space}));
        },
        [space](const Upload& d, fg::PassContext& context) {
            vkCmdUpdateBuffer(context.cmd(), context.buffer(d.space), 0, sizeof space, &space);
        });

    struct Data {
        fg::BufferHandle vertices, indices;
        fg::ImageHandle depth;
    };
    const auto& data = graph.add_pass<Data>(
        "sun shadow map", fg::PassKind::Graphics,
        [&](fg::PassBuilder& builder, Data& d) {
            d.vertices = builder.vertex_buffer(meshes.import_vertices(graph));
            d.indices = builder.index_buffer(meshes.import_indices(graph));
            fg::ImageInfo info;
            info.format = VK_FORMAT_D32_SFLOAT;
            info.size_class = fg::SizeClass::Absolute;
            info.width = (inputs.beam ? 2 : 1) * inputs.size;
            info.height = inputs.size;
            d.depth = builder.depth_stencil_attachment(builder.create_image("sun shadow depth", info),
                                                       fg::LoadOp::Clear, {.depth = 0.0f});
        },
        [&meshes, space, size = inputs.size, beam = inputs.beam](const Data& d, fg::PassContext& context) {
            const bool cutouts = meshes.has_cutouts();
            GraphicsPipelineDesc desc;
            // Both variants clip the beam half at the water level; "cutout" also samples the parts' alpha.
            use_receiver_mesh_vertices(desc, /*with_normal=*/false);
            desc.vertex_shader = "receivers/sun_shadow.vert";
            desc.fragment_shader = ShaderVariant{"receivers/sun_shadow.frag"}.define("VKWATER_CUTOUT", cutouts).file();
            desc.depth_test = true;
            desc.depth_write = true;
            const Pipeline& pipeline =
                context.pipeline(cutouts ? "sun shadow map with cutouts" : "sun shadow map", desc);
            // The cutout variant's texture (cutouts have textures: ReceiverMeshes): the white texel
            // until each draw pushes its own.
            context.bind(pipeline,
                         cutouts ? std::vector{meshes.textures().binding(-1)} : std::vector<fg::DescriptorBinding>{});
            const VkBuffer vertex_buffer = context.buffer(d.vertices);
            const VkDeviceSize offset = 0;
            vkCmdBindVertexBuffers(context.cmd(), 0, 1, &vertex_buffer, &offset);
            vkCmdBindIndexBuffer(context.cmd(), context.buffer(d.indices), 0, VK_INDEX_TYPE_UINT32);
            const auto draw_half = [&](int half, const ShadowProjection& projection, float clip_height) {
                // Each half is a size x size viewport, y flipped as the executor's (row 0 at y = +1).
                const float x = float(half) * float(size);
                const VkViewport viewport{x, float(size), float(size), -float(size), 0.0f, 1.0f};
                const VkRect2D scissor{{int32_t(half) * int32_t(size), 0}, {size, size}};
                vkCmdSetViewport(context.cmd(), 0, 1, &viewport);
                vkCmdSetScissor(context.cmd(), 0, 1, &scissor);
                ShadowPush push{};
                push.light_from_world = projection.light_from_world;
                push.clip.x = clip_height;
                for (const ReceiverDraw& draw : meshes.draws()) {
                    if (cutouts) context.push_descriptors(pipeline, {meshes.textures().binding(draw.texture)});
                    push.material.x = draw.alpha;
                    push.material.y = draw.alpha_cutoff;
                    context.push_constants(pipeline, push);
                    vkCmdDrawIndexed(context.cmd(), draw.index_count, 1, draw.first_index, draw.vertex_offset, 0);
                }
            };
            draw_half(0, space.sun, std::numeric_limits<float>::max());
            if (beam) draw_half(1, space.beam, float(beam->water_level));
        });
    return {data.depth, upload.space};
}

void SunShadowReads::declare(fg::PassBuilder& builder, const SunShadowMap* map, VkPipelineStageFlags2 stages) {
    if (!map) return;
    builder.sample("sun_shadow_map", map->depth, fg::Filter::Nearest, stages);
    builder.uniform_buffer("SunShadowSpace", map->space, stages);
    declared = true;
}

}  // namespace vkw::passes
