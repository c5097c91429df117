// The budget's cost model (cost_model.hpp).
#include "tools/vkwater/budget/cost_model.hpp"

#include "passes/frame/upscale.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <string_view>

namespace vkw::budget {
namespace {

double& at(CostDrivers& drivers, Driver driver) { return drivers[static_cast<size_t>(driver)]; }
double at(const CostDrivers& drivers, Driver driver) { return drivers[static_cast<size_t>(driver)]; }

struct KnownPass {
    const char* name;
    PassFormula formula;
};

// Prior rates on lavapipe (Mesa 22.3, 2 cores), from `vkwater render scenes/pool.json --repeat 2`
// at 800x600 and 400x300 with mesh resolutions 256 and 64; the lookup steps from lake's water
// pass at max_steps 64, 16 and 8; the photons' from pool with the adaptive kernel at map scales
// 0.5, 1 and 2 and the bilinear one at 1; the kept map's copy from pool at --spp 4
// (docs/performance-log.md "The frame-time budget"). Only their
// ratios matter once a frame has been timed; a GPU refits every factor.
// A pass of the light-space photon map, which the first sub-frame makes for all of them.
PassFormula once(std::vector<std::pair<Driver, double>> ns_per_unit) {
    return {.ns_per_unit = std::move(ns_per_unit), .condition = PassCondition::Caustics, .once_per_frame = true};
}
// A pass that runs only under `condition`.
PassFormula when(PassCondition condition, std::vector<std::pair<Driver, double>> ns_per_unit) {
    return {.ns_per_unit = std::move(ns_per_unit), .condition = condition};
}

const std::vector<KnownPass>& known_passes() {
    using D = Driver;
    static const std::vector<KnownPass> table = {
        // With the second layer the water pass costs lake 1.31-1.42 times as much (its refracted
        // rays checked against the layer, a few marched through it; docs/performance-log.md "The
        // refraction view's second layer"): about 150 ns a pixel on lake's prior of 200 ms. Each
        // scene lookup costs about 200 ns a pixel before its steps: lake's, the showcase pool's
        // and the lagoon's water passes at their cheapest settings (200x150) took 17.7, 28 and 22
        // ms more with both lookups than without, 190-230 ns a pixel and lookup at the factors
        // their passes without lookups fitted (docs/performance-log.md "The scene lookups turned off").
        {"water",
         {{{D::Pixels, 130.0},
           {D::MeshTriangles, 300.0},
           {D::LookupSteps, 1.6},
           {D::ReflectionLookupPixels, 200.0},
           {D::RefractionLookupPixels, 200.0},
           {D::SecondLayerPixels, 150.0}}}},
        {"camera medium", {{{D::Pixels, 30.0}, {D::MeshTriangles, 100.0}}}},
        {"sky", {{{D::Pixels, 20.0}}}},
        {"floor", {{{D::Pixels, 5.0}}}},
        // The views of the receiver meshes: their triangles' rates from lake's cheapest setting at
        // 200x150 with its bed at 128, 64 and 32 cells per side, 37,500, 12,900 and 6,800 triangles
        // (docs/performance-log.md "The frame-time budget"); the second layer draws what the refraction
        // view draws.
        {"receivers", {{{D::Pixels, 40.0}, {D::ReceiverTriangles, 340.0}}}},
        {"refraction view",
         when(PassCondition::RefractionView, {{D::RefractionLookupPixels, 50.0}, {D::ReceiverTriangles, 550.0}})},
        {"refraction view second layer",
         when(PassCondition::SecondLayer, {{D::SecondLayerPixels, 50.0}, {D::ReceiverTriangles, 550.0}})},
        {"mirrored reflection view",
         when(PassCondition::ReflectionView, {{D::ReflectionLookupPixels, 50.0}, {D::ReceiverTriangles, 250.0}})},
        {"calibration", {{{D::Pixels, 2.0}}}},
        // Lake's cheapest setting at 200x150 (its receivers' 37,500 triangles, each drawn into both
        // halves): 72 ms with 1024^2 texels a half, 39 ms with 256^2 (the machine shared with a
        // build); at 256^2, 15.0, 6.8 and 3.8 ms with the bed at 128, 64 and 32 cells (the
        // triangles' rate, as the views' above).
        {"sun shadow map", {{{D::ShadowTexels, 17.6}, {D::ShadowTriangles, 350.0}}}},
        {"water surface (wave sum)", {{{D::SurfaceVertices, 20.0}}}},
        {"water surface (ocean grid)", {{{D::SurfaceVertices, 20.0}}}},
        {"water mesh (wave sum)", {{{D::MeshVertices, 21.0}}}},
        {"water mesh (ocean grid)", {{{D::MeshVertices, 21.0}}}},
        // A hat photon's 4 neighbours' rays cost 95 ns when each was traced for it; shared along
        // the column it walks and with the lanes beside it, about a quarter of that (pool's photon
        // pass went from 243 to 200 ms, docs/performance-log.md "The photons' neighbours shared").
        {"caustic photons", once({{D::Photons, 10.0}, {D::HatPhotons, 24.0}, {D::PhotonTaps, 16.0}})},
        {"caustic flux clear", once({{D::MapTexels, 2.3}})},
        {"caustic resolve", once({{D::MapTexels, 18.0}})},
        {"caustic blur x", once({{D::MapTexels, 5.0}})},
        {"caustic blur y", once({{D::MapTexels, 5.0}})},
        {"keep caustic map",
         {.ns_per_unit = {{D::MapTexels, 10.0}}, .condition = PassCondition::Supersampled, .once_per_frame = true}},
        {"godray lines", when(PassCondition::Godrays, {{D::BeamColumns, 46.0}})},
        {"godray beams", when(PassCondition::Godrays, {{D::Beams, 190.0}})},
        {"godray depth", when(PassCondition::Godrays, {{D::GodrayPixels, 34.0}})},
        {"godray clear", when(PassCondition::Godrays, {{D::GodrayPixels, 5.0}})},
        {"godray resolve", when(PassCondition::Godrays, {{D::GodrayPixels, 180.0}})},
        {"godray blur x", when(PassCondition::Godrays, {{D::GodrayPixels, 32.0}})},
        {"godray blur y", when(PassCondition::Godrays, {{D::GodrayPixels, 32.0}})},
        {"godray composite", when(PassCondition::Godrays, {{D::Pixels, 32.0}})},
        {"upscale", when(PassCondition::Upscale, {{D::OutputPixels, 4.0}})},
        {"caustic layer upscale", when(PassCondition::Upscale, {{D::OutputPixels, 4.0}})},
        {"in-scatter layer upscale", when(PassCondition::Upscale, {{D::OutputPixels, 4.0}})},
        {"readback", {{{D::OutputPixels, 2.0}}}},
        {"caustic layer readback", {{{D::OutputPixels, 2.0}}}},
        {"in-scatter layer readback", {{{D::OutputPixels, 2.0}}}},
        {"present handoff", {{{D::OutputPixels, 2.0}}}},
    };
    return table;
}

// The frame's sub-frames: every pass runs in each but the photon map's.
double sub_frames(const CostDrivers& drivers) { return std::max(1.0, at(drivers, Driver::SubFrames)); }

bool holds(PassCondition condition, const CostDrivers& drivers, bool godrays, bool upscale) {
    switch (condition) {
        case PassCondition::Always: return true;
        case PassCondition::Godrays: return godrays;
        case PassCondition::Upscale: return upscale;
        case PassCondition::Supersampled: return sub_frames(drivers) > 1.0;
        case PassCondition::SecondLayer: return at(drivers, Driver::SecondLayerPixels) > 0.0;
        case PassCondition::ReflectionView: return at(drivers, Driver::ReflectionLookupPixels) > 0.0;
        case PassCondition::RefractionView: return at(drivers, Driver::RefractionLookupPixels) > 0.0;
        case PassCondition::Caustics: return at(drivers, Driver::MapTexels) > 0.0;
        case PassCondition::Count: break;
    }
    return true;
}

}  // namespace

CostDrivers cost_drivers(const Scene& scene, const Quality& quality, uint32_t width, uint32_t height) {
    CostDrivers drivers{};
    at(drivers, Driver::SubFrames) = quality.samples;
    const double scaled_width = passes::scaled_size(width, quality.render_scale);
    const double scaled_height = passes::scaled_size(height, quality.render_scale);
    at(drivers, Driver::Pixels) = scaled_width * scaled_height;
    at(drivers, Driver::OutputPixels) = double(width) * height;
    if (scene.water && quality.photon_grid > 0) {
        const double grid = quality.photon_grid;
        const double mesh = quality.mesh_resolution;
        at(drivers, Driver::SurfaceVertices) = (grid + 1.0) * (grid + 1.0);
        at(drivers, Driver::MeshVertices) = (mesh + 1.0) * (mesh + 1.0);
        at(drivers, Driver::MeshTriangles) = 2.0 * mesh * mesh;
    }
    // The light-space photon map, where the frame makes one (quality.hpp: a map scale) and the
    // caustics run.
    if (scene.water && quality.photon_grid > 0 && quality.map_scale > 0.0 && quality.caustics) {
        const double grid = quality.photon_grid;
        const double photons_per_side = grid * scene.effects.caustics.sub_photons;
        at(drivers, Driver::Photons) = photons_per_side * photons_per_side;
        const double texels_per_side = std::max(1.0, std::round(grid * quality.map_scale));
        at(drivers, Driver::MapTexels) = texels_per_side * texels_per_side;
        // The bilinear tent adds to 2 x 2 texels. The adaptive hat reaches its neighbours' landing
        // points, s = map_scale / S texels apart under flat water, so it spans about 2 s + 1 texels
        // per axis (the footprint kernel is costed as the hat).
        if (quality.caustic_kernel == CausticKernel::Bilinear) {
            at(drivers, Driver::PhotonTaps) = 4.0 * at(drivers, Driver::Photons);
        } else {
            const double span = 2.0 * quality.map_scale / scene.effects.caustics.sub_photons + 1.0;
            at(drivers, Driver::HatPhotons) = at(drivers, Driver::Photons);
            at(drivers, Driver::PhotonTaps) = span * span * at(drivers, Driver::Photons);
        }
    }
    at(drivers, Driver::LookupSteps) = at(drivers, Driver::Pixels) * quality.scene_lookups() * quality.lookup_steps;
    if (quality.reflection_lookup) at(drivers, Driver::ReflectionLookupPixels) = at(drivers, Driver::Pixels);
    if (quality.refraction_lookup) at(drivers, Driver::RefractionLookupPixels) = at(drivers, Driver::Pixels);
    if (quality.second_layer) at(drivers, Driver::SecondLayerPixels) = at(drivers, Driver::Pixels);
    double triangles = 0.0;
    for (const Receiver& receiver : scene.receivers) {
        if (receiver.terrain && quality.terrain_fraction > 0.0) {
            const double cells = terrain_cells(*receiver.terrain, quality.terrain_fraction);
            triangles += 2.0 * cells * cells;
        } else {
            triangles += double(receiver.mesh.indices.size()) / 3.0;
        }
    }
    at(drivers, Driver::ReceiverTriangles) = triangles;
    if (quality.shadow_texels > 0) {
        const double texels = quality.shadow_texels;
        at(drivers, Driver::ShadowTexels) = 2.0 * texels * texels;  // two halves (passes/receivers/sun_shadow.hpp)
        at(drivers, Driver::ShadowTriangles) = triangles;
    }
    if (quality.godray_grid > 0) {
        const double beams = double(quality.godray_grid) * quality.godray_grid;
        const double godray_scale = scene.effects.godrays.resolution_scale;
        at(drivers, Driver::Beams) = beams;
        at(drivers, Driver::BeamColumns) = beams * std::max(1.0, std::round(godray_scale * scaled_width));
        at(drivers, Driver::GodrayPixels) = at(drivers, Driver::Pixels) * godray_scale * godray_scale;
    }
    return drivers;
}

double PassFormula::runs_per_frame(const CostDrivers& drivers) const {
    return once_per_frame ? 1.0 : sub_frames(drivers);
}

double PassFormula::prior_ms(const CostDrivers& drivers) const {
    double ns = 0.0;
    for (const auto& [driver, rate] : ns_per_unit) ns += rate * at(drivers, driver);
    return ns * 1e-6 * runs_per_frame(drivers);
}

PassFormula pass_formula(const std::string& pass) {
    for (const KnownPass& known : known_passes()) {
        if (pass == known.name) return known.formula;
    }
    return {};
}

void CostModel::observe_passes(const std::vector<fg::PassTime>& passes, const CostDrivers& drivers) {
    passes_.clear();  // the frame's pass list is the one to predict from
    ++passes_revision_;
    for (const fg::PassTime& pass : passes) {
        FittedPass fitted;
        fitted.formula = pass_formula(pass.pass);
        const double prior = fitted.formula.prior_ms(drivers);
        if (prior > 0.0) {
            fitted.factor = pass.ms / prior;
        } else {
            // Taken to run in every sub-frame, as every pass but the photon map's does.
            fitted.formula = {};
            fitted.fixed_ms = pass.ms / sub_frames(drivers);
        }
        passes_[pass.pass] = fitted;
    }
}

void CostModel::observe_frame(double ms, const CostDrivers& drivers) {
    bool godrays = false, upscale = false;
    for (const auto& [name, pass] : passes_) {
        godrays = godrays || pass.formula.condition == PassCondition::Godrays;
        upscale = upscale || pass.formula.condition == PassCondition::Upscale;
    }
    const double passes = predict_passes_ms(drivers, godrays, upscale);
    if (passes > 0.0 && ms > 0.0) frame_factor_ = ms / passes;
}

double CostModel::typical_factor() const {
    std::vector<double> factors;
    for (const auto& [name, pass] : passes_) {
        if (!pass.formula.ns_per_unit.empty()) factors.push_back(pass.factor);
    }
    if (factors.empty()) return 1.0;
    std::nth_element(factors.begin(), factors.begin() + factors.size() / 2, factors.end());
    return factors[factors.size() / 2];
}

double CostModel::predict_passes_ms(const CostDrivers& drivers, bool godrays, bool upscale) const {
    double ms = 0.0;
    constexpr size_t kConditions = static_cast<size_t>(PassCondition::Count);
    std::array<bool, kConditions> timed{};  // the conditions some timed pass ran under
    for (const auto& [name, pass] : passes_) {
        timed[static_cast<size_t>(pass.formula.condition)] = true;
        if (!holds(pass.formula.condition, drivers, godrays, upscale)) continue;
        ms += pass.formula.ns_per_unit.empty() ? pass.fixed_ms * sub_frames(drivers)
                                               : pass.factor * pass.formula.prior_ms(drivers);
    }
    // Passes the timed frame did not run (godrays it had turned off, the upscale at full
    // resolution, the kept photon map at one sample, the second layer or a scene lookup turned
    // off): their priors, at the factor typical of this device. Of the upscales only the frame's:
    // the caustic and in-scatter layers' run only where a render writes those layers. Most
    // candidates miss none, and the choice predicts every candidate: the table is read only then.
    std::array<bool, kConditions> missing{};
    bool any_missing = false;
    for (size_t c = 0; c < kConditions; ++c) {
        const auto condition = static_cast<PassCondition>(c);
        missing[c] = condition != PassCondition::Always && !timed[c] && holds(condition, drivers, godrays, upscale);
        any_missing = any_missing || missing[c];
    }
    if (!any_missing) return ms;
    const double factor = typical_factor();
    for (const KnownPass& known : known_passes()) {
        const PassCondition condition = known.formula.condition;
        if (!missing[static_cast<size_t>(condition)]) continue;
        if (condition == PassCondition::Upscale && std::string_view(known.name) != "upscale") continue;
        ms += factor * known.formula.prior_ms(drivers);
    }
    return ms;
}

double CostModel::predict_ms(const CostDrivers& drivers, bool godrays, bool upscale) const {
    return frame_factor_ * predict_passes_ms(drivers, godrays, upscale);
}

}  // namespace vkw::budget
