// add_caustic_photon_pass (caustics_photons.hpp).
#include "passes/caustics/caustics_photons.hpp"

#include "engine/core/errors.hpp"
#include "engine/framegraph/pass_context.hpp"
#include "engine/vk/context.hpp"
#include "engine/vk/shader_variant.hpp"
#include "passes/caustics/caustics_bands.hpp"
#include "passes/common/zeroed_buffer.hpp"
#include "passes/water/water_surface.hpp"

#include <shader_structs/caustics/caustic_photons.comp.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <memory>
#include <numeric>
#include <optional>
#include <string>
#include <vector>

namespace vkw::passes {
namespace {

// The photon rows one work group of caustic_photons.comp covers: 8 x 8 invocations, or with the
// adaptive kernel 64 x 1, each walking kColumnRows photons down a column.
constexpr uint32_t kGroupSide = 8;
constexpr uint32_t kColumnRows = 8;  // kColumnRows in caustic_photons.comp
constexpr uint32_t kMaxGroups = 65535;

// The push constants of shaders/caustics/caustic_photons.comp, generated from its SPIR-V
// (tools/shader_structs): sub_and_flags holds S in bits 0-7, then the flags below; chunk_rows the
// chunk's first cell row | its cell rows << 16 (R <= 4096); read_x and read_y the read texels'
// columns and rows, [first, end): first | end << 16.
using CausticPhotonPush = glsl::caustic_photons_comp::Push;
constexpr uint32_t kJitterFlag = 1u << 8, kCullFlag = 1u << 9, kHeldFlag = 1u << 10;
static_assert(sizeof(CausticPhotonPush) == 128, "the push-constant size every device supports");

// Uploads the per-row read spans (vkCmdUpdateBuffer writes at most 65536 bytes a call).
fg::BufferHandle add_read_rows_upload(fg::FrameGraph& graph, std::shared_ptr<const std::vector<uint32_t>> rows) {
    struct Data {
        fg::BufferHandle rows;
    };
    const VkDeviceSize bytes = rows->size() * sizeof(uint32_t);
    const auto& upload = graph.add_pass<Data>(
        "upload caustic read rows", fg::PassKind::Transfer,
        [&](fg::PassBuilder& builder, Data& d) {
            d.rows = builder.copy_destination(builder.create_buffer("caustic read rows", {bytes}));
        },
        [rows, bytes](const Data& d, fg::PassContext& context) {
            constexpr VkDeviceSize kMaxUpdate = 65536;
            for (VkDeviceSize offset = 0; offset < bytes; offset += kMaxUpdate) {
                vkCmdUpdateBuffer(context.cmd(), context.buffer(d.rows), offset, std::min(kMaxUpdate, bytes - offset),
                                  reinterpret_cast<const char*>(rows->data()) + offset);
            }
        });
    return upload.rows;
}

}  // namespace

CausticPhotonSourcePush caustic_photon_source(const CausticInputs& in) {
    const CausticMapFrame frame = fit_caustic_map(in);
    CausticPhotonSourcePush push{};
    push.space = caustic_light_space_push(frame, in);
    for (int c = 0; c < 3; ++c) {
        push.deposit_scale[c] = frame.sun_up ? float(in.sun_irradiance[c] / frame.lsb[c]) : 0.0f;
        push.sigma_t[c] = float(in.sigma_t[c]);
    }
    return push;
}

std::vector<RowBand> caustic_photon_chunks(const fg::PassContext& context, uint32_t resolution, uint32_t sub,
                                           bool neighbour_rows) {
    const VkPhysicalDeviceLimits& limits = context.context().properties().limits;
    const VkDeviceSize row_bytes = VkDeviceSize{resolution + 1} * kWaterVertexBytes;
    // Cell rows j .. j + rows read vertex rows j .. j + rows: one extra row per chunk. With the
    // neighbours' rows, neighbour_binding's two more and the rows its aligned start adds.
    const VkDeviceSize align = std::max<VkDeviceSize>(limits.minStorageBufferOffsetAlignment, 1);
    const uint32_t extra = neighbour_rows ? static_cast<uint32_t>(3 + (align + row_bytes - 1) / row_bytes) : 1;
    return row_bands(resolution, row_bytes, 0, extra, limits.maxStorageBufferRange, align,
                     kMaxGroups * kGroupSide / sub);
}

namespace {

// A chunk's binding widened to the vertex rows its photons' neighbours read: the row before the
// chunk's first and the one after its last (where they exist), from the aligned offset at or
// before the first of them. Vulkan's offset alignments are powers of two, so that offset is a
// whole number of vertices.
struct NeighbourBinding {
    VkDeviceSize offset = 0, bytes = 0;
    uint32_t vertex_offset = 0;  // the binding's element that holds vertex (0, chunk.first)
};
NeighbourBinding neighbour_binding(const RowBand& chunk, uint32_t resolution, VkDeviceSize alignment) {
    const VkDeviceSize row_bytes = VkDeviceSize{resolution + 1} * kWaterVertexBytes;
    const VkDeviceSize align = std::max<VkDeviceSize>(alignment, 1);
    const uint32_t first_row = chunk.first > 0 ? chunk.first - 1 : 0;
    const uint32_t end_row = std::min(chunk.first + chunk.rows + 2, resolution + 1);
    const VkDeviceSize offset = first_row * row_bytes / align * align;
    return {offset, end_row * row_bytes - offset,
            static_cast<uint32_t>((chunk.first * row_bytes - offset) / kWaterVertexBytes)};
}

// The chunks' part within cell rows [first, end).
std::vector<RowBand> clip_cell_rows(const std::vector<RowBand>& chunks, uint32_t first, uint32_t end,
                                    const fg::PassContext& context, uint32_t resolution) {
    const VkDeviceSize row_bytes = VkDeviceSize{resolution + 1} * kWaterVertexBytes;
    const VkDeviceSize align =
        std::max<VkDeviceSize>(context.context().properties().limits.minStorageBufferOffsetAlignment, 1);
    // Chunks start at multiples of `step` rows (row_bands), so a start rounded down to one stays
    // aligned; the few rows before `first` that this keeps are culled in the shader.
    const uint32_t step = static_cast<uint32_t>(align / std::gcd(row_bytes, align));
    std::vector<RowBand> clipped;
    for (const RowBand& chunk : chunks) {
        const uint32_t from = std::max(chunk.first, first / step * step), to = std::min(chunk.first + chunk.rows, end);
        if (from >= to) continue;
        clipped.push_back({from, to - from, from * row_bytes, (to - from + 1) * row_bytes});
    }
    return clipped;
}

}  // namespace

fg::BufferHandle add_caustic_photon_pass(fg::FrameGraph& graph, const CausticInputs& inputs,
                                         const SunShadowMap* shadow) {
    CausticPhotonPush push{};
    push.source = caustic_photon_source(inputs);  // checks the inputs
    push.resolution = inputs.grid_resolution;
    push.sub_and_flags = inputs.sub_photons | (inputs.jitter ? kJitterFlag : 0u);
    const CausticMapFrame frame = fit_caustic_map(inputs);  // its size includes the margin for the waves
    // The read rows (pack_caustic_read_rows), made with the region; one unread entry when every
    // photon is kept (`ReadRows` must hold something).
    static const auto kNoRows = std::make_shared<const std::vector<uint32_t>>(1, 0u);
    std::shared_ptr<const std::vector<uint32_t>> read_rows = kNoRows;
    if (inputs.read_texels) {
        const CausticTexelRect& r = inputs.read_texels->bounds;
        // 16 bits per bound: a map has at most 16384 texels and its margins per side.
        if (r.x1 > 0xffffu || r.y1 > 0xffffu || r.x0 > r.x1 || r.y0 > r.y1) {
            throw InternalError("caustic photons: read texels out of range");
        }
        push.sub_and_flags |= kCullFlag;
        push.read_x = r.x0 | r.x1 << 16;
        push.read_y = r.y0 | r.y1 << 16;
        if (!inputs.read_texels->packed_rows || inputs.read_texels->packed_rows->size() != 2 * size_t{frame.height}) {
            throw InternalError("caustic photons: the read texels' rows are not the map's");
        }
        read_rows = inputs.read_texels->packed_rows;
    }
    const fg::BufferHandle rows = add_read_rows_upload(graph, std::move(read_rows));
    // The cell rows whose photons can land on a read row: a cell's photons land within
    // photon_spread of the cell's own place (caustics_read_region.hpp), and their tents reach
    // kAdaptiveSplatReach texels further (the footprint kernel kMaxFootprintTexels).
    uint32_t first_cell_row = 0, end_cell_row = inputs.grid_resolution;
    if (inputs.read_texels && std::isfinite(inputs.read_texels->photon_spread)) {
        const CausticTexelRect& r = inputs.read_texels->bounds;
        const double cell = 2.0 * inputs.half_extent / inputs.grid_resolution;
        const double reach = inputs.read_texels->photon_spread / frame.texel.y + kMaxFootprintTexels + 1.0;
        // Map row of world z: (z - corner.y) / texel.y; cell row j spans z = -E + [j, j + 1] cell.
        auto cell_row = [&](double map_row) {
            return (map_row * frame.texel.y + frame.corner.y + inputs.half_extent) / cell;
        };
        const double lo = std::floor(cell_row(r.y0 - reach)), hi = std::ceil(cell_row(r.y1 + reach));
        first_cell_row = static_cast<uint32_t>(std::clamp(lo, 0.0, double(inputs.grid_resolution)));
        end_cell_row = static_cast<uint32_t>(std::clamp(hi, double(first_cell_row), double(inputs.grid_resolution)));
    }
    // The flux holds the read texels' rectangle alone (CausticMapFrame::held), at its own width:
    // read_x and read_y are that rectangle (the read texels' bounds), and the flag says so.
    const CausticTexelRect held = frame.held;
    if (frame.holds_part()) {
        if (!inputs.read_texels || held != inputs.read_texels->bounds) {
            throw InternalError("caustic photons: the held texels are not the read texels' bounds");
        }
        push.sub_and_flags |= kHeldFlag;
    }
    const VkDeviceSize bytes = caustic_flux_bytes(frame.width, frame.height);
    const fg::BufferHandle cleared =
        add_zeroed_buffer_pass(graph, "caustic flux clear", "caustic flux", bytes, std::nullopt,
                               caustic_flux_bytes(std::max(held.width(), 1u), std::max(held.height(), 1u)));

    struct Data {
        fg::BufferHandle surface, flux;
        SunShadowReads shadow;
    };
    const auto& data = graph.add_pass<Data>(
        "caustic photons", fg::PassKind::Compute,
        [&](fg::PassBuilder& builder, Data& d) {
            d.surface = builder.read_storage("Surface", inputs.surface);
            d.flux = builder.read_write_storage("Flux", cleared);
            builder.read_storage("ReadRows", rows);
            d.shadow.declare(builder, shadow);
            if (!inputs.read_note.empty()) builder.note(inputs.read_note);
        },
        [push, kernel_variant = inputs.kernel, share_rays = inputs.share_rays_between_lanes, first_cell_row,
         end_cell_row, held](const Data& d, fg::PassContext& context) {
            if (held.width() == 0 || held.height() == 0) return;  // the frame reads no texel
            ComputePipelineDesc desc;
            // The variant: the kernel, with the sun shadow map or without.
            const char* kernel = kernel_variant == CausticKernel::Bilinear   ? "VKWATER_SPLAT_BILINEAR"
                                 : kernel_variant == CausticKernel::Adaptive ? "VKWATER_SPLAT_ADAPTIVE"
                                                                             : "VKWATER_SPLAT_FOOTPRINT";
            desc.shader = ShaderVariant{"caustics/caustic_photons.comp"}
                              .define(kernel)
                              .define("VKWATER_SUN_SHADOW", static_cast<bool>(d.shadow))
                              .define("VKWATER_LANES_SHARE_RAYS",
                                      kernel_variant == CausticKernel::Adaptive && share_rays &&
                                          context.context().features().compute_subgroup_shuffle_relative)
                              .file();
            const Pipeline& pipeline = context.pipeline(desc.shader, desc);
            const VkPhysicalDeviceLimits& limits = context.context().properties().limits;
            const uint32_t r = push.resolution, s = push.sub_and_flags & 0xffu;
            // The adaptive kernel (and the footprint's fallback to it) reads each photon's neighbours.
            const bool neighbours = kernel_variant != CausticKernel::Bilinear;
            const auto chunks = clip_cell_rows(caustic_photon_chunks(context, r, s, neighbours), first_cell_row,
                                               end_cell_row, context, r);
            const auto bands =
                row_bands(held.height(), VkDeviceSize{held.width()} * kCausticTexelBytes, kCausticFluxHeaderBytes, 0,
                          limits.maxStorageBufferRange, limits.minStorageBufferOffsetAlignment, held.height());
            // The flux buffer's header (the lost photons' count), beside the band of its rows.
            const fg::DescriptorBinding lost = context.storage_buffer("Lost", d.flux, 0, kCausticFluxHeaderBytes);
            for (const RowBand& chunk : chunks) {
                fg::DescriptorBinding surface = context.storage_buffer("Surface", d.surface, chunk.offset, chunk.bytes);
                uint32_t vertex_offset = 0;
                if (neighbours) {
                    const NeighbourBinding wide = neighbour_binding(chunk, r, limits.minStorageBufferOffsetAlignment);
                    surface.buffer.offset = wide.offset;
                    surface.buffer.range = wide.bytes;
                    vertex_offset = wide.vertex_offset;
                }
                for (const RowBand& band : bands) {
                    CausticPhotonPush p = push;
                    p.chunk_rows = chunk.first | chunk.rows << 16;
                    p.vertex_offset = vertex_offset;
                    p.band_first = held.y0 + band.first;  // a map row
                    p.band_rows = band.rows;
                    context.bind(pipeline,
                                 {surface, context.storage_buffer("Flux", d.flux, band.offset, band.bytes), lost});
                    context.push_constants(pipeline, p);
                    // The adaptive kernel's invocations walk kColumnRows photon rows each.
                    const uint32_t rows_per_invocation = kernel_variant == CausticKernel::Adaptive ? kColumnRows : 1;
                    context.dispatch(pipeline, r * s, (chunk.rows * s + rows_per_invocation - 1) / rows_per_invocation);
                }
            }
        });
    return data.flux;
}

}  // namespace vkw::passes
