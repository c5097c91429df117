// Sine surface under a vertical sun (docs/model.md section 5): h = A sin(k x + phase),
// A k = 0.3, lambda = 0.5 m, n = 1.333, clear-ocean water (sine_caustic_scene.hpp). The floor rows
// of the real-time caustic map at d = 0.5 d*, d* and 2 d* (d* the first cusp's depth) against the
// CPU double evaluation of section 5 filtered per texel (sine_floor_profile.hpp), over one whole
// wavelength of texels in the middle of the lit floor; and, before the focus, the crest texel
// against its closed form.
//
// Sizes: water 1 m square (two wavelengths), a 512-cell grid with 4 x 4 photons per cell (2048
// photons per side, 4.2M in all), a map of 128 x 8 texels over the water: texels of lambda/64 =
// 7.8 mm along x, 16 photons per texel along x and 256 per texel row along z (so the z direction
// is exact: an integer number of evenly spaced photons per texel sums the bilinear taps to one).
//
// What the map is: each photon adds its flux times tent((X_j - c)/h) to texel c (the bilinear
// splat), so as photons get denser a texel tends to E filtered by that tent, not by the texel's
// box. Two checks per depth:
// - against the tent-filtered profile, to the photon lattice's derived bound (lattice_error_bound:
//   0.43%, 0.80% and 1.75% at the three depths; measured 0.03%, 0.06% and 0.13%): the sampling
//   noise is that small, so a 2% bound is meaningful;
// - against the box-filtered profile, the 2% bound. The tent and box filters of the exact E
//   differ by themselves (computed from the CPU model and printed): 0.04% at 0.5 d*, 1.0% at 2 d*,
//   but 2.2% at d*, where the cusp (E ~ |X - X_c|^(-2/3)) lies inside one texel. A splat whose
//   footprint is at least one texel (the bilinear splat is exactly a one-texel
//   box footprint) cannot meet 2% there whatever the photon count: finer texels only shrink the
//   difference as h^(1/3) (1.8% at 256 texels, where 2 d* then reaches 1.9%). So at d* the box
//   check asserts the triangle inequality instead, |map - box| <= |map - tent| + |tent - box|,
//   with the tent term's derived bound: it still fails if the map strays from the tent-filtered
//   profile, and the 2.2% kernel bias is reported, not hidden (docs/techniques/caustics.md).

#include "tests/caustics/sine_caustic_scene.hpp"
#include "tests/support/gpu_test.hpp"

#include <cstdio>
#include <vector>

namespace vkw::test {
namespace {

// The bound on the L1 difference, relative: sum |map - ref| / sum ref over the window.
constexpr double kIssueL1 = 0.02;

SineCausticScene profile_scene(double depth_factor) {
    return {.half_extent = 0.5,
            .grid = 512,
            .sub_photons = 4,
            .texels_x = 128,
            .texels_z = 8,
            .depth_factor = depth_factor};
}

// A bound on the L1 between the map and the tent-filtered CPU profile, relative (sum over the
// window of |map - tent| over the sum of tent), channel c:
// - lattice: a texel sums photons spaced delta = |X'| dx / h texels apart (dx their spacing on the
//   surface) weighted by the tent: the midpoint rule on g(x) = phi(x) tent(X(x)). The rule is exact
//   on the tent's linear pieces but for O(dx^2 X'' / h), and each of the tent's three kinks (slope
//   jumps phi |X'|/h, 2 phi |X'|/h, phi |X'|/h) costs at most 1/8 jump dx^2: at most
//   phi |X'| dx^2 / (2 h) per branch of the floor-to-surface map against the branch's
//   phi h / |X'| in the texel: a relative error of at most delta^2 / 2, so at most
//   delta_max^2 / 2 (delta_max from max|X'|) over the window;
// - the real-time surface's normals, interpolated between vertices, move the floor points by at
//   most e (SineFloor::interpolated_normal_shift); a profile moved by e changes texel i by at most
//   (e / h) max(|tent_i+1 - tent_i|, |tent_i - tent_i-1|);
// - kSineRounding.
double lattice_error_bound(const SineCausticScene& scene, const SineFloor& sine, const std::vector<glm::dvec3>& tent,
                           const ColumnRange& window, const MapColumns& columns, int c) {
    const double delta = sine.max_stretch() * scene.photon_spacing() / columns.h;
    const double shift = sine.interpolated_normal_shift(2.0 * scene.half_extent / scene.grid);
    double moved = 0.0, total = 0.0;
    for (int i = window.first; i <= window.last; ++i) {
        moved +=
            shift / columns.h * std::max(std::abs(tent[i + 1][c] - tent[i][c]), std::abs(tent[i][c] - tent[i - 1][c]));
        total += tent[i][c];
    }
    return 0.5 * delta * delta + moved / total + kSineRounding;
}

class caustics_sine_profile : public GpuTest, public ::testing::WithParamInterface<double> {};

// One depth's run: the scene (its crest on the centre of the texel that starts at x = 0, so a
// texel average about a maximum is symmetric: k x_c + phase = pi / 2 at x_c = h / 2), the map,
// its columns, the CPU model, and the window of one whole wavelength of texels about x = 0.
// The window's kernels reach h further, and the light there comes from surface points at most
// max|X - x| away: all inside the water (checked), so the window is fully lit.
struct ProfileRun {
    SineCausticScene scene;
    passes::CausticInputs in;
    passes::CausticMapFrame frame;
    MapColumns columns;
    SineFloor sine;
    CausticRun run;
    ColumnRange window;
    std::vector<glm::dvec3> box;  // the CPU profile, box-filtered per texel
};

ProfileRun run_profile(Context& context, double depth_factor, CausticKernel kernel) {
    ProfileRun p{profile_scene(depth_factor)};
    p.in = p.scene.caustics();
    p.in.kernel = kernel;
    p.frame = passes::fit_caustic_map(p.in);
    p.columns = map_columns(p.frame);
    p.scene.phase = 0.5 * std::numbers::pi - kSineWavenumber * 0.5 * p.columns.h;
    p.sine = p.scene.cpu();
    p.run = run_caustics(context, p.scene.surface(), p.in);
    p.window = columns_centred_in(p.columns, -0.5 * kSineWavelength, 0.5 * kSineWavelength);
    EXPECT_EQ(p.window.last - p.window.first + 1, int(std::lround(kSineWavelength / p.columns.h)));
    EXPECT_LT(0.5 * kSineWavelength + 2.0 * p.columns.h + p.sine.max_reach(), p.scene.half_extent)
        << "the window is not fully lit";
    const double e = p.scene.half_extent;
    p.box = sine_floor_profile(p.sine, -e, e, p.columns.corner, p.columns.h, p.columns.count, TexelFilter::Box);
    return p;
}

TEST_P(caustics_sine_profile, FloorRowMatchesSection5) {
    const ProfileRun p = run_profile(context(), GetParam(), CausticKernel::Bilinear);
    const SineCausticScene& scene = p.scene;
    const passes::CausticMapFrame& frame = p.frame;
    const MapColumns& columns = p.columns;
    const SineFloor& sine = p.sine;
    const CausticRun& run = p.run;
    const ColumnRange& window = p.window;
    const auto& box = p.box;
    const double e = scene.half_extent;
    const auto tent = sine_floor_profile(sine, -e, e, columns.corner, columns.h, columns.count, TexelFilter::Tent);

    for (int c = 0; c < 3; ++c) {
        double to_box = 0.0, to_tent = 0.0, filters = 0.0, box_sum = 0.0, tent_sum = 0.0;
        for (int i = window.first; i <= window.last; ++i) {
            const double got = map_column_mean(run, frame, i, c, scene.half_extent);
            to_box += std::abs(got - box[i][c]);
            to_tent += std::abs(got - tent[i][c]);
            filters += std::abs(tent[i][c] - box[i][c]);
            box_sum += box[i][c];
            tent_sum += tent[i][c];
        }
        const double l1_box = to_box / box_sum, l1_tent = to_tent / tent_sum;
        const double bound = lattice_error_bound(scene, sine, tent, window, columns, c);
        std::printf(
            "d = %.2f d* = %.4f m, channel %d: L1 to the box-filtered profile %.3e (issue: %.0e), to the "
            "tent-filtered %.3e (bound %.3e); tent vs box filter %.3e\n",
            scene.depth_factor, sine.depth, c, l1_box, kIssueL1, l1_tent, bound, filters / box_sum);
        const double kernel_bias = filters / box_sum;
        // The 2% bound wherever the one-texel kernel's own bias is below it; where the bias alone
        // exceeds it (the cusp depth) the triangle inequality (header comment).
        const double box_bound = kernel_bias < kIssueL1 ? kIssueL1 : kernel_bias + bound * tent_sum / box_sum;
        if (box_bound > kIssueL1)
            std::printf(
                "  the 2%% bound against the box filter is out of reach of a one-texel kernel here "
                "(its bias alone is %.3e); asserting the triangle bound %.3e\n",
                kernel_bias, box_bound);
        EXPECT_LE(l1_box, box_bound) << "channel " << c << ": the tent and box filters of the exact E alone differ by "
                                     << kernel_bias << " (the splat's one-texel kernel; see the header comment)";
        EXPECT_LE(l1_tent, bound) << "channel " << c;
    }

    if (scene.depth_factor < 1.0) {
        // Before the focus: the crest texel against E_s T(0) exp(-sigma_t (d + A)) / (1 - (d + A)/f).
        // The texel is the tent average of E about its maximum, below the pointwise value by
        // curvature = 1 - tent_crest / E_crest (a property of E, from the CPU evaluation, whose
        // pointwise crest is first checked against the closed form); the photons add their
        // lattice error there, delta_c^2 / 2 with delta_c = (1 - (d + A)/f) dx / h, and kSineRounding.
        const int crest = columns_centred_in(columns, 0.0, columns.h).first;
        const glm::dvec3 closed = sine.crest_closed_form();
        const glm::dvec3 pointwise = sine.branch_irradiance(0.5 * columns.h);
        const double stretch = 1.0 - (sine.depth + kSineAmplitude) / sine.focal_length();
        const double delta_c = stretch * scene.photon_spacing() / columns.h;
        for (int c = 0; c < 3; ++c) {
            // branch_irradiance's central difference of X over +-1e-6/k: truncation (1e-6)^2 X'''/X'
            // ~ 1e-12 and cancellation 1e-16 / 1e-6: within 1e-9.
            EXPECT_NEAR(pointwise[c] / closed[c], 1.0, 1e-9) << "CPU evaluation vs closed form, channel " << c;
            const double curvature = 1.0 - tent[crest][c] / closed[c];
            const double tolerance = curvature + 0.5 * delta_c * delta_c + kSineRounding;
            const double got = map_column_mean(run, frame, crest, c, scene.half_extent);
            std::printf(
                "crest, channel %d: map %.6f, closed form %.6f (%.4f x flat), error %.3e, tolerance %.3e "
                "(curvature %.3e)\n",
                c, got, closed[c], 1.0 / stretch, got / closed[c] - 1.0, tolerance, curvature);
            EXPECT_NEAR(got / closed[c], 1.0, tolerance) << "channel " << c;
        }
    }
}

// The relative L1 between the map's row and the box-filtered profile over the window, channel c.
double box_l1(const ProfileRun& p, int c) {
    double to_box = 0.0, box_sum = 0.0;
    for (int i = p.window.first; i <= p.window.last; ++i) {
        to_box += std::abs(map_column_mean(p.run, p.frame, i, c, p.scene.half_extent) - p.box[i][c]);
        box_sum += p.box[i][c];
    }
    return to_box / box_sum;
}

// The footprint kernel (Tipprasert 2006's area ratio): each photon's flux spread over its sub-cell's
// footprint by area, so a texel is the box average of the photons' piecewise-constant irradiance,
// and the 2% bound against the box-filtered profile applies at every depth, the cusp's included
// (the footprints there are thin, folded quads whose flux the clipping puts in the right texels).
TEST_P(caustics_sine_profile, FootprintKernelRowMatchesBoxFilteredSection5) {
    const ProfileRun p = run_profile(context(), GetParam(), CausticKernel::Footprint);
    for (int c = 0; c < 3; ++c) {
        const double l1 = box_l1(p, c);
        std::printf("footprint kernel, d = %.2f d*, channel %d: L1 to the box-filtered profile %.3e (issue: %.0e)\n",
                    p.scene.depth_factor, c, l1, kIssueL1);
        EXPECT_LE(l1, kIssueL1) << "channel " << c;
    }
}

// The adaptive kernel (the hat of the landed lattice, integrated over each texel): a texel is the
// box average of the piecewise-linear irradiance through the photons' landing points, so with 16
// photons per texel it tends to the box-filtered profile. Before the focus (0.5 d*) the
// interpolation error is second order in the landed spacing (about a sixteenth of a texel here),
// so the profile must meet 0.2%; at and past the focus, where the cusp's |X - X_c|^(-2/3) is no
// longer smooth, the 2% of the one-texel kernels' test above.
TEST_P(caustics_sine_profile, AdaptiveKernelRowMatchesBoxFilteredSection5) {
    const ProfileRun p = run_profile(context(), GetParam(), CausticKernel::Adaptive);
    const double bound = p.scene.depth_factor < 1.0 ? 0.002 : kIssueL1;
    for (int c = 0; c < 3; ++c) {
        const double l1 = box_l1(p, c);
        std::printf("adaptive kernel, d = %.2f d*, channel %d: L1 to the box-filtered profile %.3e (bound %.0e)\n",
                    p.scene.depth_factor, c, l1, bound);
        EXPECT_LE(l1, bound) << "channel " << c;
    }
}

INSTANTIATE_TEST_SUITE_P(Depth, caustics_sine_profile, ::testing::Values(0.5, 1.0, 2.0), [](const auto& param_info) {
    return "d_" + std::to_string(int(param_info.param * 10)) + "_tenths_of_focal";
});

}  // namespace
}  // namespace vkw::test
