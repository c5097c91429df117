// The sine scene of the section-5 caustic tests: h = A sin(k x + phase) with A k = 0.3
// and lambda = 0.5 m, a vertical sun, n = 1.333, clear-ocean water (docs/model.md section 1), the
// floor at a multiple of the first cusp's depth d*. Builds the GPU inputs (water surface, caustic
// passes) and the CPU model (sine_floor_profile.hpp) of the same scene, and reads the map's rows.
#pragma once

#include "tests/caustics/caustics_support.hpp"
#include "tests/caustics/sine_floor_profile.hpp"

#include <numbers>

namespace vkw::test {

inline constexpr double kSineWavelength = 0.5, kSineSlope = 0.3, kSineIor = 1.333;
inline constexpr double kSineWavenumber = 2.0 * std::numbers::pi / kSineWavelength;
inline constexpr double kSineAmplitude = kSineSlope / kSineWavenumber;
// Clear ocean: sigma_t = sigma_a + sigma_s per RGB.
inline const glm::dvec3 kClearOceanSigmaT{1.169 + 0.028, 0.0638 + 0.035, 0.0150 + 0.039};
inline const glm::dvec3 kSineSun{1.0, 2.0, 0.5};

// What fp32 and the fixed point add to a texel or a mean of texels of these maps, relative:
// caustics_flat_test.cpp's analysis gives below 2e-5 for the photons' flux and coordinates at
// these sizes (|coordinates| <= 4 m, texels >= 7.8 mm, paths <= 2.2 m); the fixed point rounds
// at most 4 taps of 1 LSB = 1e-9 of a flat texel per photon, with at most 2^12 photons per texel
// in these tests: 1.6e-5; the CPU evaluation's own error is below 1e-5 (sine_floor_profile.hpp).
// Rounded up to 1e-4.
inline constexpr double kSineRounding = 1e-4;

struct SineCausticScene {
    double half_extent = 0.5;              // the water spans [-E, E]^2
    uint32_t grid = 256;                   // R cells per side
    uint32_t sub_photons = 1;              // S x S photons per cell
    uint32_t texels_x = 64, texels_z = 8;  // the map's texels over the water (plus a one-texel border)
    double depth_factor = 1.0;             // the floor at depth_factor d*
    double phase = 0.0;                    // radians

    SineFloor cpu() const {
        SineFloor sine;
        sine.amplitude = kSineAmplitude;
        sine.wavenumber = kSineWavenumber;
        sine.phase = phase;
        sine.ior = kSineIor;
        sine.sun_irradiance = kSineSun;
        sine.sigma_t = kClearOceanSigmaT;
        sine.depth = depth_factor * sine.first_cusp_depth();
        return sine;
    }

    passes::WaterSurfaceInputs surface() const {
        passes::WaterSurfaceInputs s;
        s.level = 0.0;
        s.half_extent = half_extent;
        s.grid_resolution = grid;
        s.waves.model = WaveModel::Sum;
        s.waves.components = {{kSineAmplitude, kSineWavelength, 0.0, phase * 180.0 / std::numbers::pi, 0.0, -1.0}};
        return s;
    }

    passes::CausticInputs caustics() const {
        passes::CausticInputs c;
        c.sun_direction = {0.0, -1.0, 0.0};
        c.sun_irradiance = kSineSun;
        c.ior = kSineIor;
        c.sigma_t = kClearOceanSigmaT;
        c.floor_height = -cpu().depth;
        c.half_extent = half_extent;
        c.max_amplitude = kSineAmplitude;
        c.sub_photons = sub_photons;
        c.map_width = texels_x + 2;
        c.map_height = texels_z + 2;
        return c;
    }

    // The photons' spacing on the surface, m.
    double photon_spacing() const { return 2.0 * half_extent / double(grid * sub_photons); }
};

// Texel column i of the map spans x in [corner + i h, corner + (i + 1) h]: under a vertical sun
// the map's coordinates are world x and z.
struct MapColumns {
    double corner = 0.0, h = 1.0;
    int count = 0;
};
inline MapColumns map_columns(const passes::CausticMapFrame& frame) {
    return {frame.corner.x, frame.texel.x, int(frame.width)};
}

// The mean of map column i over the texel rows whose centres lie within E - 1.5 texels of the
// middle (E the water's half extent: the bilinear map's rows 2 .. H - 3; the rows outside are the
// border the kernel needs, and the rows next to it miss the photons beyond the water's edge),
// channel c, W m^-2.
inline double map_column_mean(const CausticRun& run, const passes::CausticMapFrame& frame, int i, int c,
                              double half_extent) {
    double sum = 0.0;
    int rows = 0;
    for (uint32_t y = 0; y < frame.height; ++y) {
        const double z = frame.corner.y + (y + 0.5) * frame.texel.y;
        if (std::abs(z) > half_extent - 1.5 * frame.texel.y + 1e-9) continue;
        sum += run.irradiance[4 * (size_t(y) * frame.width + i) + c];
        ++rows;
    }
    return sum / double(rows);
}

// The texels whose centres lie in [x0, x1).
struct ColumnRange {
    int first = 0, last = -1;
};
inline ColumnRange columns_centred_in(const MapColumns& columns, double x0, double x1) {
    return {int(std::ceil((x0 - columns.corner) / columns.h - 0.5)),
            int(std::ceil((x1 - columns.corner) / columns.h - 0.5)) - 1};
}

}  // namespace vkw::test
