// The budget's cost model (cost_model.hpp).
#include "tools/vkwater/budget/cost_model.hpp"

#include "passes/frame/upscale.hpp"

#include <algorithm>
#include <cmath>

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
// (docs/performance.md "The frame-time budget"). Only their
// ratios matter once a frame has been timed; a GPU refits every factor.
// A pass of the light-space photon map, which the first sub-frame makes for all of them.
PassFormula once(std::vector<std::pair<Driver, double>> ns_per_unit) {
    return {.ns_per_unit = std::move(ns_per_unit), .once_per_frame = true};
}

const std::vector<KnownPass>& known_passes() {
    using D = Driver;
    static const std::vector<KnownPass> table = {
        // With the second layer the water pass costs lake 1.31-1.42 times as much (its refracted
        // rays checked against the layer, a few marched through it; docs/performance.md "The
        // refraction view's second layer"): about 150 ns a pixel on lake's prior of 200 ms.
        {"water",
         {{{D::Pixels, 130.0}, {D::MeshTriangles, 300.0}, {D::LookupSteps, 1.6}, {D::SecondLayerPixels, 150.0}}}},
        {"camera medium", {{{D::Pixels, 30.0}, {D::MeshTriangles, 100.0}}}},
        {"sky", {{{D::Pixels, 20.0}}}},
        {"floor", {{{D::Pixels, 5.0}}}},
        // The views of the receiver meshes: their triangles' rates from lake's cheapest setting at
        // 200x150 with its bed at 128, 64 and 32 cells per side, 37,500, 12,900 and 6,800 triangles
        // (docs/performance.md "The frame-time budget"); the second layer draws what the refraction
        // view draws.
        {"receivers", {{{D::Pixels, 40.0}, {D::ReceiverTriangles, 340.0}}}},
        {"refraction view", {{{D::Pixels, 50.0}, {D::ReceiverTriangles, 550.0}}}},
        {"refraction view second layer",
         {.ns_per_unit = {{D::SecondLayerPixels, 50.0}, {D::ReceiverTriangles, 550.0}}, .second_layer = true}},
        {"mirrored reflection view", {{{D::Pixels, 50.0}, {D::ReceiverTriangles, 250.0}}}},
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
        // pass went from 243 to 200 ms, docs/performance.md "The photons' neighbours shared").
        {"caustic photons", once({{D::Photons, 10.0}, {D::HatPhotons, 24.0}, {D::PhotonTaps, 16.0}})},
        {"caustic flux clear", once({{D::MapTexels, 2.3}})},
        {"caustic resolve", once({{D::MapTexels, 18.0}})},
        {"caustic blur x", once({{D::MapTexels, 5.0}})},
        {"caustic blur y", once({{D::MapTexels, 5.0}})},
        {"keep caustic map", {.ns_per_unit = {{D::MapTexels, 10.0}}, .once_per_frame = true, .supersampled = true}},
        {"godray lines", {{{D::BeamColumns, 46.0}}, true}},
        {"godray beams", {{{D::Beams, 190.0}}, true}},
        {"godray depth", {{{D::GodrayPixels, 34.0}}, true}},
        {"godray clear", {{{D::GodrayPixels, 5.0}}, true}},
        {"godray resolve", {{{D::GodrayPixels, 180.0}}, true}},
        {"godray blur x", {{{D::GodrayPixels, 32.0}}, true}},
        {"godray blur y", {{{D::GodrayPixels, 32.0}}, true}},
        {"godray composite", {{{D::Pixels, 32.0}}, true}},
        {"upscale", {{{D::OutputPixels, 4.0}}, false, true}},
        {"caustic layer upscale", {{{D::OutputPixels, 4.0}}, false, true}},
        {"in-scatter layer upscale", {{{D::OutputPixels, 4.0}}, false, true}},
        {"readback", {{{D::OutputPixels, 2.0}}}},
        {"caustic layer readback", {{{D::OutputPixels, 2.0}}}},
        {"in-scatter layer readback", {{{D::OutputPixels, 2.0}}}},
        {"present handoff", {{{D::OutputPixels, 2.0}}}},
    };
    return table;
}

// The frame's sub-frames: every pass runs in each but the photon map's.
double sub_frames(const CostDrivers& drivers) { return std::max(1.0, at(drivers, Driver::SubFrames)); }

bool runs(const PassFormula& formula, const CostDrivers& drivers, bool godrays, bool upscale) {
    return (godrays || !formula.godray) && (upscale || !formula.upscale) &&
           (sub_frames(drivers) > 1.0 || !formula.supersampled) &&
           (at(drivers, Driver::SecondLayerPixels) > 0.0 || !formula.second_layer);
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
        const double photons_per_side = grid * scene.effects.caustics.sub_photons;
        at(drivers, Driver::Photons) = photons_per_side * photons_per_side;
        const double map_scale = quality.map_scale > 0.0 ? quality.map_scale : scene.effects.caustics.map_scale;
        const double texels_per_side = std::max(1.0, std::round(grid * map_scale));
        at(drivers, Driver::MapTexels) = texels_per_side * texels_per_side;
        // The bilinear tent adds to 2 x 2 texels. The adaptive hat reaches its neighbours' landing
        // points, s = map_scale / S texels apart under flat water, so it spans about 2 s + 1 texels
        // per axis (the footprint kernel is costed as the hat).
        if (quality.map_scale > 0.0 && quality.caustic_kernel == CausticKernel::Bilinear) {
            at(drivers, Driver::PhotonTaps) = 4.0 * at(drivers, Driver::Photons);
        } else {
            const double span = 2.0 * map_scale / scene.effects.caustics.sub_photons + 1.0;
            at(drivers, Driver::HatPhotons) = at(drivers, Driver::Photons);
            at(drivers, Driver::PhotonTaps) = span * span * at(drivers, Driver::Photons);
        }
    }
    at(drivers, Driver::LookupSteps) = at(drivers, Driver::Pixels) * quality.scene_lookups * quality.lookup_steps;
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
        godrays = godrays || pass.formula.godray;
        upscale = upscale || pass.formula.upscale;
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
    bool has_godrays = false, has_upscale = false, has_supersampled = false, has_second_layer = false;
    for (const auto& [name, pass] : passes_) {
        has_godrays = has_godrays || pass.formula.godray;
        has_upscale = has_upscale || pass.formula.upscale;
        has_supersampled = has_supersampled || pass.formula.supersampled;
        has_second_layer = has_second_layer || pass.formula.second_layer;
        if (!runs(pass.formula, drivers, godrays, upscale)) continue;
        ms += pass.formula.ns_per_unit.empty() ? pass.fixed_ms * sub_frames(drivers)
                                               : pass.factor * pass.formula.prior_ms(drivers);
    }
    // Passes the timed frame did not run (godrays it had turned off, the upscale at full
    // resolution, the kept photon map at one sample, the second layer turned off): their priors, at
    // the factor typical of this device.
    const bool supersampled = sub_frames(drivers) > 1.0;
    const bool second_layer = at(drivers, Driver::SecondLayerPixels) > 0.0;
    if ((godrays && !has_godrays) || (upscale && !has_upscale) || (supersampled && !has_supersampled) ||
        (second_layer && !has_second_layer)) {
        const double factor = typical_factor();
        for (const KnownPass& known : known_passes()) {
            const bool missing =
                (godrays && !has_godrays && known.formula.godray) ||
                (upscale && !has_upscale && known.formula.upscale && std::string(known.name) == "upscale") ||
                (supersampled && !has_supersampled && known.formula.supersampled) ||
                (second_layer && !has_second_layer && known.formula.second_layer);
            if (missing) ms += factor * known.formula.prior_ms(drivers);
        }
    }
    return ms;
}

double CostModel::predict_ms(const CostDrivers& drivers, bool godrays, bool upscale) const {
    return frame_factor_ * predict_passes_ms(drivers, godrays, upscale);
}

}  // namespace vkw::budget
