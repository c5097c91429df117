// add_sun_shadow_pass and its light-space fit (sun_shadow.hpp).
#include "passes/sun_shadow.hpp"

#include "engine/core/errors.hpp"
#include "engine/framegraph/pass_context.hpp"
#include "passes/caustics_light_space.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace vkw::passes {

SunShadowSpace fit_sun_shadow(const SunShadowInputs& in) {
    bool finite = true;
    for (int k = 0; k < 3; ++k) finite = finite && std::isfinite(in.bounds_lo[k]) && std::isfinite(in.bounds_hi[k]);
    if (std::abs(glm::length(in.sun_direction) - 1.0) >= 1e-9 || !finite ||
        glm::any(glm::lessThan(in.bounds_hi, in.bounds_lo)) || in.size < 1 || in.size > 16384) {
        throw InternalError("sun shadow: inputs out of range (accepted: a unit sun direction, a finite box with "
                            "lo <= hi, 1 <= size <= 16384); got size " + std::to_string(in.size));
    }
    const glm::dvec3 s = in.sun_direction;
    glm::dvec3 u, v;
    branchless_basis(s, u, v);
    // The box's corners in light space: (u, v) across the map, d = s.P along the beam.
    glm::dvec3 lo(std::numeric_limits<double>::max()), hi(-std::numeric_limits<double>::max());
    for (int corner = 0; corner < 8; ++corner) {
        const glm::dvec3 p((corner & 1) ? in.bounds_hi.x : in.bounds_lo.x, (corner & 2) ? in.bounds_hi.y : in.bounds_lo.y,
                           (corner & 4) ? in.bounds_hi.z : in.bounds_lo.z);
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
    SunShadowSpace space{};
    for (int col = 0; col < 4; ++col) {
        space.light_from_world[col * 4 + 0] = float(row_x[col]);
        space.light_from_world[col * 4 + 1] = float(row_y[col]);
        space.light_from_world[col * 4 + 2] = float(row_z[col]);
        space.light_from_world[col * 4 + 3] = col == 3 ? 1.0f : 0.0f;
    }
    space.params[0] = float(std::max(extent.x, extent.y) / in.size);
    space.params[1] = float(extent.z);
    space.params[2] = float(in.size);
    return space;
}

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
            info.width = info.height = inputs.size;
            d.depth = builder.depth_stencil_attachment(builder.create_image("sun shadow depth", info),
                                                       fg::LoadOp::Clear, {.depth = 0.0f});
        },
        [&meshes, space](const Data& d, fg::PassContext& context) {
            GraphicsPipelineDesc desc;
            desc.vertex_shader = "receivers/sun_shadow.vert";
            desc.layout.push_constant_bytes = sizeof space.light_from_world;
            desc.vertex_bindings = {{0, 6 * sizeof(float), VK_VERTEX_INPUT_RATE_VERTEX}};
            desc.vertex_attributes = {{0, 0, VK_FORMAT_R32G32B32_SFLOAT, 0}};
            desc.depth_test = true;
            desc.depth_write = true;
            const Pipeline& pipeline = context.pipeline("sun shadow map", desc);
            context.bind(pipeline, std::vector<fg::DescriptorBinding>{});
            context.push_constants(pipeline, space.light_from_world, static_cast<uint32_t>(sizeof space.light_from_world));
            const VkBuffer vertex_buffer = context.buffer(d.vertices);
            const VkDeviceSize offset = 0;
            vkCmdBindVertexBuffers(context.cmd(), 0, 1, &vertex_buffer, &offset);
            vkCmdBindIndexBuffer(context.cmd(), context.buffer(d.indices), 0, VK_INDEX_TYPE_UINT32);
            for (const ReceiverDraw& draw : meshes.draws()) {
                vkCmdDrawIndexed(context.cmd(), draw.index_count, 1, draw.first_index, draw.vertex_offset, 0);
            }
        });
    return {data.depth, upload.space};
}

}  // namespace vkw::passes
