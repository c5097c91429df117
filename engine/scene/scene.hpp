// The scene as the renderers see it: camera, sun, sky and floor, in double precision
// (the CPU reference renderer works in doubles). Units: metres, y up, right-handed;
// irradiance in W m^-2 and radiance in W m^-2 sr^-1 per RGB channel (PHYSICS.md section 1).
//
// The default member values are the defaults of the optional fields of the scene file
// (scenes/README.md); the loader reads them from here, so they are stated only once.
#pragma once

#include <filesystem>
#include <string>

#include <glm/glm.hpp>

namespace vkw {

struct Camera {
    glm::dvec3 position{0.0, 0.0, 0.0};   // required in a scene file
    glm::dvec3 target{0.0, 0.0, -1.0};    // required in a scene file; != position
    double fov_y_deg = 60.0;              // full vertical field of view, in (1, 179)
    double near_plane = 0.05;             // metres, 0 < near_plane < far_plane
    double far_plane = 500.0;             // metres
    double exposure = 1.0;                // linear scale on radiance before display, > 0
};

struct Sun {
    // Unit vector, the direction the light TRAVELS: y < 0 when the sun is above the horizon.
    // A sun below the horizon (y >= 0) is valid and lights nothing.
    glm::dvec3 direction{0.0, -1.0, 0.0};
    // Irradiance on a plane normal to the beam, W m^-2 per channel. The default of 1 makes
    // radiances read directly as multiples of the sun's irradiance.
    glm::dvec3 irradiance{1.0, 1.0, 1.0};
};

struct Sky {
    glm::dvec3 radiance{0.0, 0.0, 0.0};   // constant sky radiance, W m^-2 sr^-1; required
};

// Horizontal Lambertian plane y = height: a square of side 2 * half_extent centred
// under the origin (x and z in [-half_extent, half_extent]).
struct FloorPlane {
    double height = -1.5;                 // metres; the pool floor 1.5 m below the water level
    glm::dvec3 albedo{0.5, 0.5, 0.5};     // in [0, 1] per channel
    double half_extent = 10.0;            // metres, > 0
};

struct Scene {
    std::filesystem::path source;         // the file it was loaded from, as given to the loader
    std::string description;              // free text saying what the scene exercises
    Camera camera;
    Sun sun;
    Sky sky;
    FloorPlane floor;
};

// Direction TOWARD the sun for elevation `el` above the horizon and azimuth `az`, both in
// degrees: u = (cos(el) sin(az), sin(el), -cos(el) cos(az)). Azimuth 0 faces -z ("north",
// glTF's default forward), 90 faces +x ("east"). Exact at multiples of 90 degrees, so an
// overhead sun is exactly (0, 1, 0). The sun's travelling direction is -u.
glm::dvec3 direction_toward_sun(double elevation_deg, double azimuth_deg);

// Right-handed world-to-view matrix for the camera, up = +y. When the view direction is
// within about 2.6 degrees of vertical (|dot(dir, +y)| > 0.999) +y cannot define "up", so
// -z (north) is used instead: looking straight down or up, north is at the top of the image.
glm::dmat4 view_matrix(const Camera& camera);

}  // namespace vkw
