// The frame-time budget's cost model: what a frame at a candidate setting will take on this
// device, fitted to the frames it has timed.
//
// Each pass's cost is a formula in what drives it (pixels, triangles, photons, map texels, beams)
// with prior rates measured on lavapipe (2 cores, pool at 800x600; docs/performance-log.md "The
// frame-time budget"), times a factor fitted to that pass's measured time: on another device or
// in another scene the factor absorbs the difference (lake's water pass costs about five times
// pool's per pixel; a GPU about a hundredth of lavapipe). A pass the table does not know costs
// what it was measured at, whatever the setting. The frame's measured time over the sum of its
// passes' predictions is one more factor: per-pass timing submits each pass alone, which is
// slower than the frame's single submission, and the viewer's frame includes its present passes.
#pragma once

#include "engine/framegraph/executor.hpp"
#include "engine/scene/scene.hpp"
#include "tools/vkwater/budget/quality.hpp"

#include <array>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace vkw::budget {

// What a frame's passes cost in proportion to.
enum class Driver : uint8_t {
    Pixels,                  // the scene's passes' pixels: the output's times the resolution scale squared
    OutputPixels,            // the output's pixels: the upscale, the readback, the window's hand-off
    SurfaceVertices,         // the water surface grid's vertices, (photon grid + 1)^2
    MeshVertices,            // the water mesh's vertices
    MeshTriangles,           // the water mesh's triangles
    Photons,                 // photons traced
    HatPhotons,              // photons whose kernel is shaped by their 4 neighbours, traced too (not the bilinear tent)
    PhotonTaps,              // photons times the texels each one's kernel adds to (about; see cost_drivers)
    MapTexels,               // the light-space caustic map's texels
    Beams,                   // godray beams
    BeamColumns,             // godray beams times the godray image's columns (a beam's walk)
    GodrayPixels,            // the godray image's pixels
    LookupSteps,             // pixels times scene lookups times their most steps
    ReflectionLookupPixels,  // the scene's passes' pixels where the reflected rays look the scene up, else 0
    RefractionLookupPixels,  // the same for the refracted rays
    SecondLayerPixels,       // the scene's passes' pixels where the refraction view's second layer runs, else 0
    ShadowTexels,            // the sun shadow map's texels (both of its halves), 0 where the frame makes none
    ShadowTriangles,         // the receiver meshes' triangles drawn into the sun shadow map
    ReceiverTriangles,       // the receiver meshes' triangles, drawn by each view of them (terrain at its fraction)
    SubFrames,               // the frame's sub-frames (its samples per pixel): every pass runs in each, but
                             // the light-space photon map's, made once by the first
    Count
};

using CostDrivers = std::array<double, static_cast<size_t>(Driver::Count)>;

// The drivers of a frame of `scene` at `quality` for an output of width x height.
CostDrivers cost_drivers(const Scene& scene, const Quality& quality, uint32_t width, uint32_t height);

// What a pass needs to run, beyond the frame itself.
enum class PassCondition : uint8_t {
    Always,
    Godrays,         // the godrays
    Upscale,         // resolution scale below 1
    Supersampled,    // more than one sub-frame (keeps the photon map for the others)
    SecondLayer,     // the refraction view's second layer
    ReflectionView,  // the reflected rays' scene lookup
    RefractionView,  // the refracted rays' scene lookup
    Caustics,        // the light-space photon map (its photons, clear, resolve and blur)
    Count
};

// A pass's prior cost formula: nanoseconds per unit of each driver on lavapipe; empty terms when
// the table does not know the pass.
struct PassFormula {
    std::vector<std::pair<Driver, double>> ns_per_unit;
    PassCondition condition = PassCondition::Always;
    bool once_per_frame = false;  // the photon map's: in the first sub-frame only
    // Over all of the frame's sub-frames.
    double prior_ms(const CostDrivers& drivers) const;
    double runs_per_frame(const CostDrivers& drivers) const;
};
PassFormula pass_formula(const std::string& pass);

class CostModel {
public:
    // A per-pass timing of a frame whose drivers were `drivers`: refits every pass's factor.
    void observe_passes(const std::vector<fg::PassTime>& passes, const CostDrivers& drivers);
    // The whole frame's measured time at `drivers`: refits the frame factor.
    void observe_frame(double ms, const CostDrivers& drivers);

    // The predicted frame time at `drivers`, with or without the godrays' passes and the upscale.
    double predict_ms(const CostDrivers& drivers, bool godrays, bool upscale) const;
    // The same before the frame factor: the sum of the passes' predictions.
    double predict_passes_ms(const CostDrivers& drivers, bool godrays, bool upscale) const;
    bool fitted() const { return !passes_.empty(); }
    // Counts the per-pass refits: predict_passes_ms changes only when it does.
    uint64_t passes_revision() const { return passes_revision_; }
    double frame_factor() const { return frame_factor_; }

private:
    struct FittedPass {
        PassFormula formula;
        double factor = 1.0;    // measured over prior, at the last timing
        double fixed_ms = 0.0;  // a pass without a formula: its measured time per sub-frame
    };
    double typical_factor() const;  // for passes never timed: the median of the fitted ones
    std::map<std::string, FittedPass> passes_;
    double frame_factor_ = 1.0;
    uint64_t passes_revision_ = 0;
};

}  // namespace vkw::budget
