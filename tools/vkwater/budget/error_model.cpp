// The budget's error table (error_model.hpp).
#include "tools/vkwater/budget/error_model.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

namespace vkw::budget {
namespace {

struct Entry {
    double value;
    double excess;  // the largest relMSE excess over pool, lake, ocean, box, showcase/pool, showcase/lagoon
};

// docs/sweeps/budget_error_terms.csv, the largest excess of each knob's value over its scenes
// (tests/budget/error_model_test.cpp checks that this table is that file's).
const std::vector<Entry>& table(Knob knob) {
    // Above 1, the smallest (most negative) change of any scene, so that going down from there
    // is not underestimated.
    static const std::vector<Entry> render_scale = {{2.0, -0.0172189}, {1.0, 0.0},        {0.75, 0.0134196},
                                                    {0.5, 0.0481425},  {0.35, 0.0834085}, {0.25, 0.495608}};
    // The caustic knobs' entries are per unit of caustic visibility (quality.hpp): each scene's
    // excess over its visibility, the largest of them (pool's visibility is 0.944).
    static const std::vector<Entry> photon_grid_fraction = {
        {1.0, 0.0}, {0.5, 0.0199534}, {0.25, 0.0218984}, {0.125, 0.0649117}};
    static const std::vector<Entry> mesh_resolution = {{256, 0.0}, {128, 0.0006656}, {64, 0.0150687}};
    static const std::vector<Entry> godray_grid = {
        {64, 0.00216061}, {32, 0.00337027}, {16, 0.00301587}, {0, 0.00357407}};
    // Below one sample's 0 (the gains), the smallest change of any scene with a box reference.
    static const std::vector<Entry> samples_per_pixel = {{1, 0.0}, {4, -0.0171892}, {9, -0.0219511}, {16, -0.0233395}};
    static const std::vector<Entry> lookup_steps = {{64, 0.0}, {16, 0.0013757}, {8, 0.0039557}};
    static const std::vector<Entry> bilinear_kernel = {
        {1.0, 0.00991741}, {0.5, 0.00941222}, {0.25, 0.0214294}, {0.125, 0.0}};
    static const std::vector<Entry> map_scale_fraction = {{1.0, 0.0}, {0.5, 0.0270338}};
    static const std::vector<Entry> second_layer = {{1.0, 0.0}, {0.0, 0.0013903}};
    static const std::vector<Entry> shadow_texels = {{1024, 0.0}, {512, 0.00042679}, {256, 0.00165248}};
    static const std::vector<Entry> terrain_fraction = {{1.0, 0.0}, {0.5, 0.0}, {0.25, 0.0002221}};
    static const std::vector<Entry> reflection_lookup = {{1.0, 0.0}, {0.0, 0.135684}};
    static const std::vector<Entry> refraction_lookup = {{1.0, 0.0}, {0.0, 0.128119}};
    switch (knob) {
        case Knob::LookupSteps: return lookup_steps;
        case Knob::RenderScale: return render_scale;
        case Knob::SamplesPerPixel: return samples_per_pixel;
        case Knob::PhotonGridFraction: return photon_grid_fraction;
        case Knob::MeshResolution: return mesh_resolution;
        case Knob::GodrayGrid: return godray_grid;
        case Knob::BilinearKernel: return bilinear_kernel;
        case Knob::MapScaleFraction: return map_scale_fraction;
        case Knob::SecondLayer: return second_layer;
        case Knob::ShadowTexels: return shadow_texels;
        case Knob::TerrainFraction: return terrain_fraction;
        case Knob::ReflectionLookup: return reflection_lookup;
        case Knob::RefractionLookup: return refraction_lookup;
    }
    return render_scale;
}

}  // namespace

const char* knob_name(Knob knob) {
    switch (knob) {
        case Knob::RenderScale: return "render_scale";
        case Knob::SamplesPerPixel: return "samples_per_pixel";
        case Knob::PhotonGridFraction: return "photon_grid_fraction";
        case Knob::MeshResolution: return "mesh_resolution";
        case Knob::GodrayGrid: return "godray_grid";
        case Knob::LookupSteps: return "lookup_steps";
        case Knob::BilinearKernel: return "bilinear_kernel";
        case Knob::MapScaleFraction: return "map_scale_fraction";
        case Knob::SecondLayer: return "second_layer";
        case Knob::ShadowTexels: return "shadow_texels";
        case Knob::TerrainFraction: return "terrain_fraction";
        case Knob::ReflectionLookup: return "reflection_lookup";
        case Knob::RefractionLookup: return "refraction_lookup";
    }
    return "";
}

double error_term(Knob knob, double value) {
    const std::vector<Entry>& entries = table(knob);
    // Above the table's first (finest) step nothing is lost: the measured scenes' own settings.
    // The kernel's entries are photon grid fractions, each the bilinear kernel's excess over the
    // scene's kernel at that grid: no step is finer than another.
    const bool ordered = knob != Knob::BilinearKernel && knob != Knob::SamplesPerPixel;
    const bool finer = knob == Knob::GodrayGrid ? value > entries.front().value : value >= entries.front().value;
    if (ordered && finer && value != 0.0) return knob == Knob::GodrayGrid ? 0.0 : entries.front().excess;
    const Entry* nearest = &entries.front();
    for (const Entry& entry : entries) {
        if (std::abs(entry.value - value) < std::abs(nearest->value - value)) nearest = &entry;
    }
    return nearest->excess;
}

// The sampled rows' table, from the most rows down: k^2 samples per pixel as k times the rows
// (where both measured twice the rows, the larger gain), then the resolution scales below 2.
const std::vector<Entry>& sampling_table() {
    static const std::vector<Entry> entries = [] {
        std::vector<Entry> rows;
        for (auto it = table(Knob::SamplesPerPixel).rbegin(); it != table(Knob::SamplesPerPixel).rend(); ++it) {
            if (it->value > 1.0) rows.push_back({std::sqrt(it->value), it->excess});
        }
        for (const Entry& scale : table(Knob::RenderScale)) {
            const auto same =
                std::find_if(rows.begin(), rows.end(), [&](const Entry& e) { return e.value == scale.value; });
            if (same != rows.end()) {
                same->excess = std::min(same->excess, scale.excess);
            } else {
                rows.push_back(scale);
            }
        }
        return rows;
    }();
    return entries;
}

double resolution_error(double rows_fraction) {
    const std::vector<Entry>& entries = sampling_table();  // from 4 down to 0.25
    const double f = std::clamp(rows_fraction, entries.back().value, entries.front().value);
    for (size_t i = 1; i < entries.size(); ++i) {
        const Entry &above = entries[i - 1], &below = entries[i];
        if (f < below.value) continue;
        const double t = std::log2(above.value / f) / std::log2(above.value / below.value);
        return above.excess + t * (below.excess - above.excess);
    }
    return entries.back().excess;
}

ErrorPrediction predict_error(const Quality& quality, const Quality& top, double output_rows) {
    const double output = output_rows / kErrorTableRows;
    // Below full scale the frame is stretched to the output after its samples are averaged, and
    // the samples count as no more rows: measured, 4 samples at scales 0.75 and 0.5 sampled pool
    // and lake as 1.1-1.3 times the rows, not 2 (docs/performance-log.md "The frame-time budget").
    const auto sampled_rows = [output](const Quality& q) {
        return q.render_scale * (q.render_scale < 1.0 ? 1.0 : std::sqrt(double(q.samples))) * output;
    };
    const bool fewer_samples_alone = quality.samples != top.samples && quality.render_scale == top.render_scale;
    std::vector<std::pair<const char*, double>> terms = {
        {fewer_samples_alone ? "samples per pixel" : "resolution scale",
         resolution_error(sampled_rows(quality)) - resolution_error(sampled_rows(top))},
    };
    // The caustic knobs' terms scale with what the caustics can change in a pixel.
    const double visibility = top.caustic_visibility;
    // Caustics turned off lose what the scene's previews measured (caustics_offered in quality.cpp
    // offers them only then), and the caustic knobs' terms no longer count.
    const bool caustics_off = top.caustics && !quality.caustics;
    if (caustics_off) {
        const double measured = top.measured_off.caustics;
        terms.push_back({"caustics off",
                         measured >= 0.0 ? kMeasuredTermBound * measured : std::numeric_limits<double>::infinity()});
    }
    if (top.photon_grid > 0) {
        terms.push_back({"photon grid", caustics_off
                                            ? 0.0
                                            : visibility * error_term(Knob::PhotonGridFraction,
                                                                      double(quality.photon_grid) / top.photon_grid)});
        terms.push_back({"water mesh", error_term(Knob::MeshResolution, quality.mesh_resolution) -
                                           error_term(Knob::MeshResolution, top.mesh_resolution)});
    }
    // The steps count where a lookup still runs; each lookup turned off adds its own term (measured
    // at the scene's own steps: with both off, lake's 0.1283 and the showcase pool's 0.0180 lie
    // under the sums of their own two lookups' excesses, 0.1301 and 0.0224).
    if (top.lookup_steps > 0 && quality.lookup_steps > 0) {
        terms.push_back({"scene lookup steps", error_term(Knob::LookupSteps, quality.lookup_steps) -
                                                   error_term(Knob::LookupSteps, top.lookup_steps)});
    }
    // An on/off knob turned off: this scene's own loss where its previews measured it (made a bound,
    // kMeasuredTermBound), else the table's worst case.
    const auto off_term = [](double measured, Knob knob) {
        return measured >= 0.0 ? kMeasuredTermBound * measured : error_term(knob, 0.0);
    };
    if (top.reflection_lookup && !quality.reflection_lookup) {
        terms.push_back(
            {"reflection lookup off", off_term(top.measured_off.reflection_lookup, Knob::ReflectionLookup)});
    }
    if (top.refraction_lookup && !quality.refraction_lookup) {
        terms.push_back(
            {"refraction lookup off", off_term(top.measured_off.refraction_lookup, Knob::RefractionLookup)});
    }
    if (top.map_scale > 0.0 && !caustics_off) {
        const bool bilinear = quality.caustic_kernel == CausticKernel::Bilinear;
        // Measured against the scene's kernel at each photon grid: it grows as the grid coarsens.
        const double grid_fraction = top.photon_grid > 0 ? double(quality.photon_grid) / top.photon_grid : 1.0;
        terms.push_back({"caustic kernel", bilinear && top.caustic_kernel != CausticKernel::Bilinear
                                               ? visibility * error_term(Knob::BilinearKernel, grid_fraction)
                                               : 0.0});
        terms.push_back(
            {"caustic map scale", visibility * error_term(Knob::MapScaleFraction, quality.map_scale / top.map_scale)});
    }
    if (top.godray_grid > 0) {
        terms.push_back({"godrays", error_term(Knob::GodrayGrid, quality.godray_grid) -
                                        error_term(Knob::GodrayGrid, top.godray_grid)});
    }
    // The layer's march takes a quarter of the lookup steps: below the scene's own it finds nothing,
    // and the lookup steps' term already holds the layer's loss. The sweep measured exactly that:
    // at 16 steps lake and the showcase pool lose what the layer off loses (0.0013757 and 0.00098328
    // against 0.0013903 and 0.00098328), so the layer's term counts only at the scene's own steps.
    // A refraction lookup turned off takes the layer with it, and its own term (measured so) holds
    // the layer's loss.
    if (top.second_layer && quality.refraction_lookup && quality.lookup_steps >= top.lookup_steps) {
        terms.push_back({"refraction second layer",
                         quality.second_layer ? 0.0 : off_term(top.measured_off.second_layer, Knob::SecondLayer)});
    }
    if (top.shadow_texels > 0) {
        terms.push_back({"sun shadow map", error_term(Knob::ShadowTexels, quality.shadow_texels) -
                                               error_term(Knob::ShadowTexels, top.shadow_texels)});
    }
    if (top.terrain_fraction > 0.0) {
        terms.push_back({"terrain detail", error_term(Knob::TerrainFraction, quality.terrain_fraction)});
    }
    ErrorPrediction prediction;
    double largest = 0.0;
    for (const auto& [name, term] : terms) {
        const double added = std::max(0.0, term);
        prediction.excess += added;
        if (added > largest) {
            largest = added;
            prediction.dominant = name;
        }
    }
    return prediction;
}

}  // namespace vkw::budget
