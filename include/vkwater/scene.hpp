// A scene built in code instead of read from a file: the same fields as a scene file
// (scenes/README.md), named as there, with the same defaults and ranges. World::load takes it;
// it is checked by the same loader as a file, so a value out of range is an InvalidInput naming
// its field as the file would ("sun.irradiance[0]: 1e+40 is out of range ..."). What these structs
// leave out (the FFT ocean, terrain and glTF receivers, floor tiles, the water's shading and the
// effects' settings) a host sets with WorldOptions::overrides, the CLI's --set
// ("effects.godrays.mode=off").
#pragma once

#include <vkwater/world.hpp>

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace vkwater {

using Rgb = std::array<double, 3>;
using Vec3 = std::array<double, 3>;

// Where the sunlight comes from: a compass bearing (0 toward -z, 90 toward +x) and an elevation
// above the horizon (scenes/README.md, "Angles").
struct Sun {
    double elevation_deg = 60.0;    // -90 to 90
    double azimuth_deg = 0.0;       // -360 to 360
    Rgb irradiance{1.0, 1.0, 1.0};  // W m^-2 on a plane normal to the beam, each 0 to 1e30
};

// The sky's radiance: one value in every direction, or a gradient from the zenith to the horizon.
struct Sky {
    Rgb radiance{0.3, 0.45, 0.7};  // W m^-2 sr^-1, every direction (when gradient is empty)
    struct Gradient {
        Rgb zenith{0.3, 0.45, 0.7};
        Rgb horizon{0.8, 0.85, 0.9};
        std::optional<Rgb> ground;  // below the horizon; empty: the horizon's radiance
        double exponent = 0.5;      // > 0: small values keep the zenith colour down to low elevations
    };
    std::optional<Gradient> gradient;
};

// The Lambertian floor: the square |x|, |z| <= half_extent at y = height.
struct Floor {
    double height = -1.5;  // m
    Rgb albedo{0.5, 0.5, 0.5};
    double half_extent = 10.0;  // m
};

// One component of the waves: a sine, or a Gerstner wave when steepness > 0.
struct Wave {
    double amplitude = 0.0;      // m
    double wavelength = 1.0;     // m
    double direction_deg = 0.0;  // direction of travel: 0 is +x, 90 is +z
    double phase_deg = 0.0;
    double steepness = 0.0;  // 0 to 1
};

// The water: a square of side 2 half_extent at mean height level, its surface flat or a sum of the
// waves (for the FFT ocean: overrides, "water.waves.model=fft" and its fields).
struct Water {
    double level = 0.0;              // m
    double ior = 1.333;              // 1 to 2
    double half_extent = 10.0;       // m: the water covers |x|, |z| <= half_extent
    bool infinite = false;           // true: no edge, to the horizon (half_extent is not read)
    uint32_t grid_resolution = 256;  // the photon grid's cells per side, 2 to 4096
    double time = 0.0;               // s, the waves' clock (a frame's Frame::time_seconds replaces it)
    std::vector<Wave> waves;         // empty: flat water
};

// What the water absorbs and scatters: a named preset ("pure", "clear-ocean", "coastal",
// "turbid-harbour"), or, with preset empty, the coefficients.
struct Medium {
    std::string preset = "pure";
    Rgb sigma_a{0.0, 0.0, 0.0};  // 1/m
    Rgb sigma_s{0.0, 0.0, 0.0};  // 1/m
    double g = 0.0;              // Henyey-Greenstein's mean cosine, -1 < g < 1
};

// A shape that receives caustics and is reflected and refracted by the water.
struct Receiver {
    enum class Shape { Box, Sphere, Plane };
    Shape shape = Shape::Box;
    Vec3 half_size{0.5, 0.5, 0.5};  // m: a box's half sides; a plane's x and z
    double radius = 0.5;            // m: a sphere's
    std::string name;               // for messages; empty: its field path, receivers[i]
    Rgb albedo{0.5, 0.5, 0.5};
    Vec3 translation{0.0, 0.0, 0.0};
    Vec3 rotation_deg{0.0, 0.0, 0.0};  // about x, then y, then z (the world's axes)
    Vec3 scale{1.0, 1.0, 1.0};
};

struct Scene {
    std::string description;
    Camera camera;  // the scene's camera (World::scene_camera); each frame gives its own
    Sun sun;
    Sky sky;
    Floor floor;
    std::optional<Water> water{Water{}};  // a World needs water
    Medium medium;
    std::vector<Receiver> receivers;
};

// The scene as the JSON text of a scene file: what World::load(device, scene) reads, and what a
// host can save to render the same scene with the CLI (`vkwater render FILE`).
std::string scene_json(const Scene& scene);

}  // namespace vkwater
