// The GPU inverse FFT (shaders/water/ocean_fft.comp through passes/water/water_surface_fft.hpp)
// on its own: against a naive double-precision DFT on a 16 x 16 grid, and against the CPU's
// double FFT (engine/water/fft.hpp) from 32 to 1024 points. The GPU transforms grids of vec4
// elements, two complex planes each (xy, zw); the tests use several grids so that the grid
// offsets and the pairing are exercised too. Inputs are fp32 values, so the references see
// exactly what the GPU sees and only the transform's error is measured.
#include "engine/framegraph/executor.hpp"
#include "engine/vk/resources.hpp"
#include "engine/water/counter_rng.hpp"
#include "engine/water/fft.hpp"
#include "passes/water/water_surface_fft.hpp"
#include "tests/support/gpu_test.hpp"
#include "tests/water_gpu/fp32_error.hpp"

#include <cmath>
#include <complex>
#include <cstdio>
#include <cstring>
#include <numbers>
#include <vector>

namespace vkw::test {
namespace {

using Complex = std::complex<double>;

// Standard normal values, rounded to fp32: plane p, element e.
std::vector<Complex> random_planes(uint32_t n, uint32_t planes) {
    std::vector<Complex> values(std::size_t(planes) * n * n);
    for (std::size_t e = 0; e < values.size(); ++e) {
        const auto g = gaussian_pair(99, int64_t(e), n);
        values[e] = {double(float(g[0])), double(float(g[1]))};
    }
    return values;
}

// Where plane p's element e lives in the GPU's grids: grid p / 2, in xy (even p) or zw.
std::size_t float_index(std::size_t p, std::size_t e, std::size_t plane_size) {
    return 4 * ((p / 2) * plane_size + e) + 2 * (p % 2);
}

// Runs the rows and columns passes in place on a host-visible buffer imported into the graph
// (initial state: the host's write; final state: the host's read). `planes` is even.
std::vector<Complex> gpu_inverse_fft(Context& context, const std::vector<Complex>& input, uint32_t n, uint32_t planes) {
    const std::size_t size = std::size_t(n) * n;
    const VkDeviceSize bytes = input.size() * 2 * sizeof(float);
    Buffer buffer(context, {bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, true}, "fft grids");
    float* mapped = static_cast<float*>(buffer.mapped());
    for (std::size_t p = 0; p < planes; ++p) {
        for (std::size_t e = 0; e < size; ++e) {
            mapped[float_index(p, e, size)] = float(input[p * size + e].real());
            mapped[float_index(p, e, size) + 1] = float(input[p * size + e].imag());
        }
    }
    {
        fg::ImportedBuffer imported{buffer.handle(), bytes};
        imported.initial = {VK_PIPELINE_STAGE_2_HOST_BIT, VK_ACCESS_2_HOST_WRITE_BIT};
        imported.final_state = fg::access_state(fg::Use::HostRead, fg::PassKind::Transfer);
        fg::PipelineStore pipelines;
        fg::FrameGraph graph;
        const fg::BufferHandle grids = graph.import_buffer("fft grids", imported);
        graph.request_output(passes::add_inverse_fft_passes(graph, grids, n, planes / 2));
        graph.compile(1, 1);
        fg::FrameExecutor executor(context, graph, pipelines, {.check_finite = true, .timing = fg::TimingMode::None});
        executor.execute();
    }
    std::vector<Complex> output(input.size());
    for (std::size_t p = 0; p < planes; ++p) {
        for (std::size_t e = 0; e < size; ++e) {
            output[p * size + e] = {mapped[float_index(p, e, size)], mapped[float_index(p, e, size) + 1]};
        }
    }
    return output;
}

// out[r][c] = sum over (b, a) of in[b][a] exp(+2 pi i (a c + b r) / n), term by term.
std::vector<Complex> naive_inverse_dft(const Complex* in, uint32_t n) {
    std::vector<Complex> out(std::size_t(n) * n);
    for (uint32_t r = 0; r < n; ++r) {
        for (uint32_t c = 0; c < n; ++c) {
            Complex sum = 0.0;
            for (uint32_t b = 0; b < n; ++b) {
                for (uint32_t a = 0; a < n; ++a) {
                    const double angle = 2.0 * std::numbers::pi * double((a * c + b * r) % n) / n;
                    sum += in[b * n + a] * std::polar(1.0, angle);
                }
            }
            out[r * n + c] = sum;
        }
    }
    return out;
}

// Each plane's outputs within inverse_fft_error of that plane's sum |input|.
void expect_planes_near(const std::vector<Complex>& gpu, const std::vector<Complex>& input,
                        const std::vector<Complex>& reference, uint32_t n, uint32_t planes) {
    const std::size_t size = std::size_t(n) * n;
    double worst = 0.0;
    for (uint32_t p = 0; p < planes; ++p) {
        double sum_abs = 0.0;
        for (std::size_t e = 0; e < size; ++e) sum_abs += std::abs(input[p * size + e]);
        const double tolerance = inverse_fft_error(sum_abs, n);
        for (std::size_t e = 0; e < size; ++e) {
            const double error = std::abs(gpu[p * size + e] - reference[p * size + e]);
            ASSERT_LE(error, tolerance) << "n " << n << ", plane " << p << ", element " << e;
            worst = std::max(worst, error / tolerance);
        }
    }
    std::printf("n = %u: worst error / tolerance %.4f\n", n, worst);
}

using water_gpu_fft = GpuTest;

TEST_F(water_gpu_fft, InverseFftOf16x16EqualsTheNaiveDft) {
    constexpr uint32_t kN = 16, kPlanes = 6;
    const std::vector<Complex> input = random_planes(kN, kPlanes);
    std::vector<Complex> reference;
    for (uint32_t p = 0; p < kPlanes; ++p) {
        const std::vector<Complex> plane = naive_inverse_dft(input.data() + p * kN * kN, kN);
        reference.insert(reference.end(), plane.begin(), plane.end());
    }
    expect_planes_near(gpu_inverse_fft(context(), input, kN, kPlanes), input, reference, kN, kPlanes);
}

TEST_F(water_gpu_fft, InverseFftEqualsTheCpuFftFrom32To1024Points) {
    for (uint32_t n : {32u, 64u, 128u, 256u, 512u, 1024u}) {
        const uint32_t planes = n <= 256 ? 4 : 2;  // keep the 1024^2 run short on lavapipe
        const std::vector<Complex> input = random_planes(n, planes);
        std::vector<Complex> reference;
        for (uint32_t p = 0; p < planes; ++p) {
            std::vector<Complex> plane(input.begin() + p * n * n, input.begin() + (p + 1) * n * n);
            fft_inverse_2d(plane, n);
            reference.insert(reference.end(), plane.begin(), plane.end());
        }
        expect_planes_near(gpu_inverse_fft(context(), input, n, planes), input, reference, n, planes);
    }
}

}  // namespace
}  // namespace vkw::test
