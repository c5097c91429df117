// vkwater compare A.exr B.exr [--mask M.exr] [--layer NAME]: A against the reference B, one line
// per metric (relMSE, FLIP, bias, L*u*v*), definitions in tools/metrics/metrics.hpp.
#include "engine/core/errors.hpp"
#include "engine/image/exr_io.hpp"
#include "tools/metrics/metrics.hpp"
#include "tools/vkwater/commands.hpp"

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
};

std::string described(const std::string& path, const ImageRGBA32F& image) {
    return path + " (" + metrics::size_text(image.width, image.height) + ")";
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
    const ImageRGBA32F* mask_image = mask ? &*mask : nullptr;
    metrics::Metrics result;
    if (args.layer.empty()) {
        result = metrics::compare_images(test, reference, mask_image);
    } else {
        metrics::layer_view(test, args.layer, args.test);  // throws, naming the file, if it is missing
        metrics::layer_view(reference, args.layer, args.reference);
        result = metrics::compare_layer(test, reference, args.layer, mask_image);
    }
    std::printf("relMSE %.6g\n", result.rel_mse);
    std::printf("FLIP %.6g\n", result.flip_mean);
    std::printf("bias %.6g\n", result.bias);
    std::printf("L*u*v* %.6g\n", result.luv_mean);
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
    return [args] { return run_compare(*args); };
}

}  // namespace vkw::cli
