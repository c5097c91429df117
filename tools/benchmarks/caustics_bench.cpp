// caustics_bench: what the surface caustics cost on this device.
// For each photon grid R^2 (one photon per water-grid cell, a map of one texel per cell):
//  1. the caustic passes of one frame (flux clear, photon trace + int64 fixed-point splat,
//     resolve), each submitted alone and fence-timed on the CPU clock (the frame graph's timing
//     on CPU devices), median of --runs frames after one warm-up frame (which also compiles
//     llvmpipe's shader variants); photons per second;
//  2. scatter-only kernels with the photon pass's 12 atomics per photon into a target of the same
//     size, timed the same way in the same frames: int64 fixed point (the photon pass's
//     accumulation), the same through a workgroup tile in shared memory (where the device has
//     shaderSharedInt64Atomics; its map read back and compared with the global kernel's, which it
//     must equal bit for bit), and 32-bit float by a compare-and-swap loop; the ratio scatter /
//     (trace + splat) (the goal: at least 0.5, so that tracing costs no more than the deposit it
//     feeds);
//  3. a 2-thread C++ scatter of the same photons (private maps + reduction; shared map with
//     atomic fetch_add), median of --runs;
//  4. where the device has shaderBufferFloat32AtomicAdd (vkw::Context does not enable it): the
//     int64 and the native float32 atomicAdd scatter kernels on a second device that enables it
//     (native_scatter_device.hpp), timed the same way.
// Scene: a sine of slope 0.3 (lambda 2 m, 20 degrees from x) on water 8 m square, the floor 2 m
// down, the sun (0.5, -1, 0.2) normalised, sigma_t (0.3, 0.1, 0.05) /m.
// Prints Markdown tables; no time is asserted (speed is measured, not tested). The exit status is
// 1 when the tile kernel's map differs from the global one's, and with --validate (the smoke test,
// with the validation layer) for any validation message.
#include "engine/core/errors.hpp"
#include "engine/framegraph/executor.hpp"
#include "engine/vk/context.hpp"
#include "engine/vk/resources.hpp"
#include "engine/vk/validation_log.hpp"
#include "passes/caustics/caustics_photons.hpp"
#include "passes/caustics/caustics_resolve.hpp"
#include "passes/present/readback.hpp"
#include "passes/water/water_surface.hpp"
#include "tools/benchmarks/caustic_scatter_passes.hpp"
#include "tools/benchmarks/cpu_scatter.hpp"
#include "tools/benchmarks/native_scatter_device.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <memory>
#include <numbers>
#include <string>
#include <vector>

using namespace vkw;

namespace {

constexpr uint32_t kAtomicsPerPhoton = 12;  // 2 x 2 bilinear taps x RGB
constexpr uint32_t kMinGrid = 64, kMaxGrid = 2048;
constexpr int kMaxRuns = 100;

struct Options {
    std::vector<uint32_t> grids{128, 256, 512, 1024, 2048};
    int runs = 5;
    bool validate = false;
    CausticKernel kernel = CausticKernel::Bilinear;  // the scatter kernels mirror the bilinear one's atomics
};

[[noreturn]] void usage_error(const std::string& message) {
    std::fprintf(stderr,
                 "caustics_bench: %s\nusage: caustics_bench [--grids R,R,...] [--runs N] [--kernel K] [--validate]\n"
                 "  --grids  photon grids per side, each in [%u, %u] (default 128,256,512,1024,2048)\n"
                 "  --runs   timed frames per grid (median), in [1, %d] (default 5)\n"
                 "  --kernel the photon pass's splat: bilinear (default; 12 atomics per photon, as the scatter\n"
                 "           kernels) or adaptive\n",
                 message.c_str(), kMinGrid, kMaxGrid, kMaxRuns);
    std::exit(2);
}

long parse_number(const std::string& text, const std::string& what) {
    char* end = nullptr;
    const long value = std::strtol(text.c_str(), &end, 10);
    if (text.empty() || *end != '\0') usage_error(what + ": '" + text + "' is not a whole number");
    return value;
}

Options parse(int argc, char** argv) {
    Options options;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        const bool has_value = i + 1 < argc;
        if (arg == "--grids" && has_value) {
            options.grids.clear();
            std::string list = argv[++i];
            for (size_t start = 0; start <= list.size();) {
                const size_t comma = std::min(list.find(',', start), list.size());
                const long grid = parse_number(list.substr(start, comma - start), "--grids");
                if (grid < long(kMinGrid) || grid > long(kMaxGrid)) {
                    usage_error("--grids: " + std::to_string(grid) + " is outside [" + std::to_string(kMinGrid) + ", " +
                                std::to_string(kMaxGrid) + "]");
                }
                options.grids.push_back(uint32_t(grid));
                start = comma + 1;
            }
        } else if (arg == "--runs" && has_value) {
            const long runs = parse_number(argv[++i], "--runs");
            if (runs < 1 || runs > kMaxRuns) {
                usage_error("--runs: " + std::to_string(runs) + " is outside [1, " + std::to_string(kMaxRuns) + "]");
            }
            options.runs = int(runs);
        } else if (arg == "--kernel" && has_value) {
            const std::string kernel = argv[++i];
            if (kernel != "bilinear" && kernel != "adaptive")
                usage_error("--kernel: '" + kernel + "' is not bilinear or adaptive");
            options.kernel = kernel == "adaptive" ? CausticKernel::Adaptive : CausticKernel::Bilinear;
        } else if (arg == "--validate") {
            options.validate = true;
        } else {
            usage_error("unknown or incomplete argument '" + arg + "'");
        }
    }
    return options;
}

double median(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    return values.empty() ? 0.0 : values[values.size() / 2];
}

passes::WaterSurfaceInputs bench_surface(uint32_t grid) {
    passes::WaterSurfaceInputs surface;
    surface.half_extent = 4.0;
    surface.grid_resolution = grid;
    surface.waves.model = WaveModel::Sum;
    surface.waves.components = {{0.3 / std::numbers::pi, 2.0, 20.0, 0.0, 0.0, -1.0}};  // A k = 0.3
    return surface;
}

passes::CausticInputs bench_caustics(const passes::WaterSurfaceInputs& surface) {
    passes::CausticInputs in;
    in.grid_resolution = surface.grid_resolution;
    in.half_extent = surface.half_extent;
    in.max_amplitude = surface.waves.components[0].amplitude;
    in.sun_direction = glm::normalize(glm::dvec3(0.5, -1.0, 0.2));
    in.sigma_t = {0.3, 0.1, 0.05};
    in.floor_height = -2.0;
    in.fit_margin = 0.25;  // the waves deflect photons sideways by at most ~0.15 m at this depth
    in.map_width = in.map_height = surface.grid_resolution + 2;  // one texel per cell
    return in;
}

struct GridFigures {
    uint32_t grid = 0;
    std::map<std::string, double> pass_ms;  // median per pass
    double cpu_private_ms = 0.0, cpu_atomic_ms = 0.0;
    vkwbench::NativeScatterTimes native;  // zero when the device has no native float atomics
    bool tile_measured = false;           // the device has shared-memory int64 atomics
    bool tile_identical = false;          // and the tile kernel's map equals the global kernel's
};

GridFigures measure(Context& context, uint32_t grid, int runs, bool native_float, CausticKernel kernel) {
    const passes::WaterSurfaceInputs surface = bench_surface(grid);
    passes::CausticInputs in = bench_caustics(surface);
    in.kernel = kernel;
    const passes::CausticMapFrame frame = passes::fit_caustic_map(in);
    fg::PipelineStore pipelines;
    fg::FrameGraph graph;
    in.surface = passes::add_water_surface_pass(graph, surface);
    const passes::CausticMap map =
        passes::add_caustic_resolve_pass(graph, passes::add_caustic_photon_pass(graph, in), in);
    graph.request_output(map.irradiance);
    const fg::BufferHandle global_target =
        vkwbench::add_caustic_scatter_pass(graph, vkwbench::ScatterKind::FixedPoint64, grid, frame);
    vkwbench::add_caustic_scatter_pass(graph, vkwbench::ScatterKind::FloatCas32, grid, frame);
    // The tile kernel and the global one, read back after the last frame to compare.
    const bool tile = context.features().shared_int64_atomics;
    const VkDeviceSize target_bytes = vkwbench::scatter_target_bytes(vkwbench::ScatterKind::FixedPoint64, frame);
    Buffer global_host(context, {target_bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT, true}, "global scatter readback");
    Buffer tile_host(context, {target_bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT, true}, "tile scatter readback");
    passes::add_readback_pass(graph, global_target, global_host.handle(), target_bytes, "global scatter readback");
    if (tile) {
        const fg::BufferHandle tile_target =
            vkwbench::add_caustic_scatter_pass(graph, vkwbench::ScatterKind::FixedPoint64Tile, grid, frame);
        passes::add_readback_pass(graph, tile_target, tile_host.handle(), target_bytes, "tile scatter readback");
    }
    graph.compile(1, 1);
    fg::FrameExecutor executor(context, graph, pipelines, {.check_finite = false, .timing = fg::TimingMode::Fences});

    std::map<std::string, std::vector<double>> times;
    for (int frame_index = 0; frame_index <= runs; ++frame_index) {
        const fg::FrameReport report = executor.execute();
        if (frame_index == 0) continue;  // warm-up: llvmpipe compiles its shader variants
        for (const fg::PassTime& pass : report.passes) times[pass.pass].push_back(pass.ms);
    }
    GridFigures figures;
    figures.grid = grid;
    for (const auto& [pass, ms] : times) figures.pass_ms[pass] = median(ms);
    figures.tile_measured = tile;
    figures.tile_identical = tile && std::memcmp(global_host.mapped(), tile_host.mapped(), target_bytes) == 0;

    const vkwbench::ScatterPush push = vkwbench::scatter_push(grid, frame);
    std::vector<double> private_ms, atomic_ms;
    for (int run = 0; run < runs; ++run) {
        private_ms.push_back(vkwbench::cpu_scatter(vkwbench::CpuScatterMethod::PrivateBuffers, push).ms);
        atomic_ms.push_back(vkwbench::cpu_scatter(vkwbench::CpuScatterMethod::SharedAtomics, push).ms);
    }
    figures.cpu_private_ms = median(private_ms);
    figures.cpu_atomic_ms = median(atomic_ms);
    if (native_float) {
        figures.native = vkwbench::time_native_scatter(context, push, runs);
    }
    return figures;
}

void print_tables(const std::vector<GridFigures>& all, const std::string& native_missing) {
    const std::string fixed = vkwbench::scatter_pass_name(vkwbench::ScatterKind::FixedPoint64);
    const std::string cas = vkwbench::scatter_pass_name(vkwbench::ScatterKind::FloatCas32);
    const std::string tile = vkwbench::scatter_pass_name(vkwbench::ScatterKind::FixedPoint64Tile);
    std::printf(
        "\nCaustic passes (ms, median):\n\n"
        "| grid | photons | flux clear | photons (trace + splat) | resolve | photons/s |\n"
        "| --- | --- | --- | --- | --- | --- |\n");
    for (const GridFigures& f : all) {
        const double photons = double(f.grid) * f.grid, trace = f.pass_ms.at("caustic photons");
        std::printf("| %u^2 | %.0f | %.2f | %.2f | %.2f | %.1f M |\n", f.grid, photons,
                    f.pass_ms.at("caustic flux clear"), trace, f.pass_ms.at("caustic resolve"), photons / trace / 1e3);
    }
    std::printf(
        "\nScatter only, %u atomics per photon into the same map (ms, median; M atomic adds/s):\n\n"
        "| grid | trace + splat | int64 scatter | ratio int64 scatter / (trace + splat) | int64 rate | "
        "float32 CAS scatter | float32 CAS rate | CPU 2 threads, private maps | CPU 2 threads, atomics |\n"
        "| --- | --- | --- | --- | --- | --- | --- | --- | --- |\n",
        kAtomicsPerPhoton);
    for (const GridFigures& f : all) {
        const double adds = double(f.grid) * f.grid * kAtomicsPerPhoton;
        const double trace = f.pass_ms.at("caustic photons"), int64 = f.pass_ms.at(fixed), f32 = f.pass_ms.at(cas);
        std::printf("| %u^2 | %.2f | %.2f | %.2f | %.0f M/s | %.2f | %.0f M/s | %.2f (%.0f M/s) | %.2f (%.0f M/s) |\n",
                    f.grid, trace, int64, int64 / trace, adds / int64 / 1e3, f32, adds / f32 / 1e3, f.cpu_private_ms,
                    adds / f.cpu_private_ms / 1e3, f.cpu_atomic_ms, adds / f.cpu_atomic_ms / 1e3);
    }
    std::printf(
        "\nThe int64 scatter through a workgroup tile in shared memory (the same map, bit for bit; ms, median):\n\n"
        "| grid | int64 scatter | int64 tile scatter | tile / global time | maps equal |\n"
        "| --- | --- | --- | --- | --- |\n");
    for (const GridFigures& f : all) {
        if (!f.tile_measured) {
            std::printf("| %u^2 | %.2f | not measured (no shaderSharedInt64Atomics) | - | - |\n", f.grid,
                        f.pass_ms.at(fixed));
            continue;
        }
        std::printf("| %u^2 | %.2f | %.2f | %.2f | %s |\n", f.grid, f.pass_ms.at(fixed), f.pass_ms.at(tile),
                    f.pass_ms.at(tile) / f.pass_ms.at(fixed), f.tile_identical ? "yes" : "NO");
    }
    if (!native_missing.empty()) {
        std::printf("\nNative float atomics: not measured (%s).\n", native_missing.c_str());
        return;
    }
    std::printf(
        "\nNative float atomics, on a second device with VK_EXT_shader_atomic_float (ms, median; M atomic "
        "adds/s):\n\n"
        "| grid | int64 scatter | float32 atomicAdd scatter | float32 / int64 time | int64 rate | float32 rate |\n"
        "| --- | --- | --- | --- | --- | --- |\n");
    for (const GridFigures& f : all) {
        const double adds = double(f.grid) * f.grid * kAtomicsPerPhoton;
        std::printf("| %u^2 | %.2f | %.2f | %.2f | %.0f M/s | %.0f M/s |\n", f.grid, f.native.int64_ms,
                    f.native.float32_ms, f.native.float32_ms / f.native.int64_ms, adds / f.native.int64_ms / 1e3,
                    adds / f.native.float32_ms / 1e3);
    }
}

}  // namespace

int main(int argc, char** argv) {
    const Options options = parse(argc, argv);
    std::shared_ptr<ValidationLog> log;
    std::string native_missing;
    try {
        std::vector<GridFigures> all;
        {
            ContextOptions context_options;
            context_options.validation = options.validate;
            Context context(context_options);
            log = context.shared_validation_log();
            native_missing = vkwbench::native_float_atomics_missing(context);
            std::printf(
                "device: %s; timing: one submission per pass, fence-timed on the CPU clock; %d runs per "
                "grid after one warm-up; %s splat kernel%s\n",
                context.device_name().c_str(), options.runs,
                options.kernel == CausticKernel::Adaptive ? "adaptive" : "bilinear",
                options.validate ? "; validation on" : "");
            for (const uint32_t grid : options.grids) {
                all.push_back(measure(context, grid, options.runs, native_missing.empty(), options.kernel));
                std::fprintf(stderr, "grid %u done\n", grid);
            }
        }
        print_tables(all, native_missing);
        for (const GridFigures& f : all) {
            if (f.tile_measured && !f.tile_identical) {
                std::fprintf(stderr, "caustics_bench: grid %u: the tile kernel's map differs from the global one's\n",
                             f.grid);
                return 1;
            }
        }
    } catch (const std::exception& e) {
        std::fprintf(stderr, "caustics_bench: %s\n", e.what());
        return 1;
    }
    if (options.validate && !log->failures().empty()) {
        for (const std::string& message : log->failures()) std::fprintf(stderr, "validation: %s\n", message.c_str());
        return 1;
    }
    return 0;
}
