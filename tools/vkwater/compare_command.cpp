// vkwater compare A.exr B.exr [--mask M.exr] [--layer NAME] [--downsample N]: A against the
// reference B, one line per metric (relMSE, FLIP, bias, L*u*v*; definitions in
// tools/metrics/metrics.hpp); with --downsample N the same four again with both images (and the
// mask) box-downsampled by N (tools/metrics/downsample.hpp); without --layer, the relMSE of the
// caustic and in-scatter layers when both images carry them, else "n/a" and why.
#include "engine/core/errors.hpp"
#include "engine/image/exr_io.hpp"
#include "tools/metrics/downsample.hpp"
#include "tools/metrics/metrics.hpp"
#include "tools/metrics/reference_errors.hpp"
#include "tools/vkwater/commands.hpp"

#include <algorithm>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>

namespace vkw::cli {
namespace {

struct CompareArgs {
    std::string test;
    std::string reference;
    std::string mask;
    std::string layer;
    int downsample = 1;
};

std::string described(const std::string& path, const ImageRGBA32F& image) {
    return path + " (" + metrics::size_text(image.width, image.height) + ")";
}

// One line per metric; `suffix` says at what resolution they were measured.
void print_metrics(const metrics::Metrics& result, const std::string& suffix) {
    std::printf("relMSE%s %.6g\n", suffix.c_str(), result.rel_mse);
    std::printf("FLIP%s %.6g\n", suffix.c_str(), result.flip_mean);
    std::printf("bias%s %.6g\n", suffix.c_str(), result.bias);
    std::printf("L*u*v*%s %.6g\n", suffix.c_str(), result.luv_mean);
}

int run_compare(const CompareArgs& args) {
    const ImageRGBA32F test = read_exr(args.test);
    const ImageRGBA32F reference = read_exr(args.reference);
    // Name the files here: the library only knows "test" and "reference".
    if (test.width != reference.width || test.height != reference.height) {
        throw UserError("cannot compare " + described(args.test, test) + " with " +
                        described(args.reference, reference) + ": the sizes differ");
    }
    std::optional<ImageRGBA32F> mask;
    if (!args.mask.empty()) {
        mask = read_exr(args.mask);
        if (mask->width != reference.width || mask->height != reference.height) {
            throw UserError("the mask " + described(args.mask, *mask) + " does not match the images " +
                            described(args.reference, reference));
        }
    }
    if (args.downsample > std::min(reference.width, reference.height)) {
        throw UserError("--downsample: " + std::to_string(args.downsample) + " is out of range for " +
                        described(args.reference, reference) + " (accepted: 1 to " +
                        std::to_string(std::min(reference.width, reference.height)) + ")");
    }
    if (!args.layer.empty()) {
        metrics::layer_view(test, args.layer, args.test);  // throws, naming the file, if it is missing
        metrics::layer_view(reference, args.layer, args.reference);
    }
    const ImageRGBA32F* mask_image = mask ? &*mask : nullptr;
    auto compare = [&](const ImageRGBA32F& a, const ImageRGBA32F& b, const ImageRGBA32F* m) {
        return args.layer.empty() ? metrics::compare_images(a, b, m) : metrics::compare_layer(a, b, args.layer, m);
    };
    print_metrics(compare(test, reference, mask_image), "");
    if (args.downsample > 1) {
        std::optional<ImageRGBA32F> small_mask;
        if (mask) small_mask = metrics::box_downsample_mask(*mask, args.downsample);
        const ImageRGBA32F small_reference = metrics::box_downsample(reference, args.downsample);
        print_metrics(compare(metrics::box_downsample(test, args.downsample), small_reference,
                              small_mask ? &*small_mask : nullptr),
                      " (" + std::to_string(args.downsample) + "x box-downsampled to " +
                          metrics::size_text(small_reference.width, small_reference.height) + ")");
    }
    if (args.layer.empty()) {
        for (const char* layer : {metrics::kCausticLayer, metrics::kInScatterLayer}) {
            std::printf("%s relMSE %s\n", layer,
                        metrics::layer_rel_mse(test, reference, layer, mask_image).text(true).c_str());
        }
    }
    return kExitOk;
}

}  // namespace

Run add_compare_command(CLI::App& app) {
    auto args = std::make_shared<CompareArgs>();
    CLI::App* command = app.add_subcommand(
        "compare", "Compare a linear HDR OpenEXR image with a reference: relMSE, HDR-FLIP, bias, L*u*v*");
    command->add_option("test", args->test, "Test image (OpenEXR)")->required();
    command->add_option("reference", args->reference, "Reference image (OpenEXR), e.g. the CPU ground truth")
        ->required();
    command->add_option("--mask", args->mask, "Only pixels whose R is > 0.5 in this OpenEXR image count");
    command->add_option("--layer", args->layer, "Compare this extra layer (e.g. caustic) instead of R, G, B");
    command
        ->add_option("--downsample", args->downsample,
                     "Also compare both images averaged over N x N pixel blocks (4 separates energy errors "
                     "from sub-texel misplacement)")
        ->check(CLI::Range(1, 4096))
        ->capture_default_str();
    command->footer(
        "Examples:\n"
        "  vkwater compare build/pool.exr build/pool-ref.exr\n"
        "  vkwater compare build/pool.exr build/pool-ref.exr --layer caustic --downsample 4\n");
    return [args] { return run_compare(*args); };
}

}  // namespace vkw::cli
