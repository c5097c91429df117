// The frame-time budget's error model: how much error a candidate setting adds to the scene's own
// settings, without a reference. One term per knob, looked up in a table measured once on the
// six of the scenes that have a reference (tools/benchmarks/budget_error_terms.sh writes
// docs/sweeps/budget_error_terms.csv): each entry is the largest relMSE excess any of those scenes
// showed with that knob alone at that value, so the table errs towards overestimating. Terms add
// up: docs/performance-log.md "The frame-time budget" checks that against combined settings.
//
// Two terms are more than one figure per knob value: the resolution scale's follows the rows
// actually sampled, samples per pixel counted as rows (predict_error below), and the bilinear kernel's is measured at each photon
// grid, since the tent's excess over the hat grows as the grid coarsens.
//
// One factor is derived per scene: the caustic knobs' terms (photon grid, kernel, map scale) are
// weights per unit of caustic visibility (quality.hpp: the largest share of the sun's light that
// can reach a receiver under the water and return to the camera), fitted as the largest of each
// measured scene's excess over its visibility, and scaled by the scene's own. The ocean's floor,
// 30 m down in coastal water (visibility 3e-4), makes its caustic knobs nearly free, as the sweep
// measured them (no excess at any photon grid).
//
// The on/off knobs' terms (a scene lookup, the refraction view's second layer, the caustics) are
// measured on the scene itself where the command could render it: small frames with the knob on and
// off (tools/vkwater/budget_previews.hpp, Quality::measured_off); the table's entry stands in
// elsewhere. A measured term is made a bound as the table's are: times the largest ratio of the
// sweep's excess to the previews' over the sweep's scenes (below).
//
// What it is not yet: the other error bounds derived per effect (the mesh's sag in pixels, the
// photons seen per texel) with fitted weights, which would follow a scene's wavelengths and depths
// instead of the measured scenes' worst case.
#pragma once

#include "tools/vkwater/budget/quality.hpp"

#include <string>

namespace vkw::budget {

struct ErrorPrediction {
    double excess = 0.0;   // predicted relMSE above the scene's own settings
    std::string dominant;  // the knob whose term is largest ("" when none adds any)
};

// The table's figures are for images of kErrorTableRows rows (400x300, against references of that
// size). The resolution scale's term follows the rows actually sampled: at an output of
// `output_rows`, scale s with k^2 samples per pixel samples the image as s * k * output_rows rows
// would (the strata's centres are a k-times finer image's pixel centres) at s = 1, and as
// s * output_rows below it, where the stretch to the output follows the samples, and its term is the
// table's error at that many rows over the error at the top's (both as fractions of
// kErrorTableRows, interpolated in log2 between the table's steps: the resolution scales from 0.25x
// up to 1x, twice the rows, and 3x and 4x from 9 and 16 samples per pixel). An output larger than
// the table's averages more samples per reference pixel, so a given scale costs less error there.
inline constexpr double kErrorTableRows = 300.0;

// The table's entries are the largest excess of the sweep's six scenes, bounds over them; a term the
// previews measured is an estimate for one scene, and beside the bounds it would look cheaper than it
// is (box's refraction lookup off, measured 0.0088, beat the table's 0.0172 for half the rows, which
// costs box itself 0.0036, and the viewer took it). So a measured term counts times the largest ratio
// of the sweep's excess to the previews' for every term the sweep put above 0.0005
// (tools/benchmarks/budget_previews.sh at 42810c3: the showcase pool's second layer, 0.00098328 over
// 0.000658 = 1.494; lake's reflection lookup 1.478; docs/performance-log.md "The on/off knobs measured on
// the scene").
inline constexpr double kMeasuredTermBound = 1.5;
ErrorPrediction predict_error(const Quality& quality, const Quality& top, double output_rows = kErrorTableRows);

// The table's relMSE at `rows_fraction` times kErrorTableRows sampled rows, relative to rendering
// kErrorTableRows at one sample (0 at 1, negative above it).
double resolution_error(double rows_fraction);

// One knob's term: the table's excess at `value` (a resolution scale, a photon grid fraction, a
// mesh resolution, a godray grid, lookup steps, the photon grid fraction at which the bilinear
// kernel replaces the scene's, the map scale as a fraction of the scene's, samples per pixel, the
// second layer on or off, the shadow map's texels, the terrain's cells as a fraction of its own,
// a scene lookup on or off),
// the nearest step's where the table has no such value.
enum class Knob : uint8_t {
    RenderScale,
    SamplesPerPixel,  // gains (negative) over one sample, which resolution_error counts as rows
    PhotonGridFraction,
    MeshResolution,
    GodrayGrid,
    LookupSteps,
    BilinearKernel,
    MapScaleFraction,
    SecondLayer,       // 1: the refraction view's second layer runs, 0: turned off
    ShadowTexels,      // the sun shadow map's texels per side
    TerrainFraction,   // the terrain receivers' cells per side over their own
    ReflectionLookup,  // 1: the reflected rays look the scene up, 0: turned off
    RefractionLookup   // 1: the refracted rays look the scene up, 0: turned off
};
double error_term(Knob knob, double value);
const char* knob_name(Knob knob);  // its name in docs/sweeps/budget_error_terms.csv

}  // namespace vkw::budget
