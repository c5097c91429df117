// A scene as POV-Ray 3.7 input that renders the sun's irradiance on the floor, for an
// independent cross-check of the CPU reference renderer's floor caustics.
//
// What the file holds: the sun as a parallel light of colour E_s shooting photons
// (refraction on, reflection off: the model drops reflected sunlight); the water body as
// one closed mesh2 (engine/water/water_volume.hpp's mesh: the surface grid at the
// analytic positions with the analytic normals, walls and a bottom just under the floor),
// a perfect dielectric (pigment rgbf 1, Fresnel reflection with conserve_energy, so that
// photons carry T = 1 - R) filled with an absorbing `media` of absorption sigma_t (photons
// honour media in a `hollow` object; they ignore fade_power); the floor as a plane of
// pigment 1, diffuse 1, no ambient. The walls and the bottom of the body are opaque: the
// model's sunlight enters the water through its surface only. The camera is orthographic,
// looks straight down from 1 mm above the floor over a window of the floor, and sees nothing
// but the floor, so a pixel's value is the photon estimate of the floor's sun irradiance at
// its centre in W m^-2, times camera_transmittance (POV-Ray's diffuse has no 1/pi, and shadow
// rays through a photon target are blocked, so no unrefracted direct sunlight is added).
//
// Axes: vkwater is right-handed, POV-Ray left-handed; the writer negates z, so the picture
// is not mirrored. Image row 0 (the top) is the window's z0 edge (north, -z), column 0 its
// x0 edge: pixel (i, j) of a W x H render is centred on
//   x = x0 + (i + 0.5) (x1 - x0) / W,  z = z0 + (j + 0.5) (z1 - z0) / H.
//
// POV-Ray's own traits (measured by tests/povray): the photon gather radius grows where the
// photons are sparse and shrinks where they crowd, which biases focal lines; a fixed
// gather radius makes the bias uniform. Render with +FE for OpenEXR (half floats).
#pragma once

#include "engine/scene/scene.hpp"

#include <cstdint>
#include <string>

namespace vkw::pov {

// A rectangle of the floor, world metres, x0 < x1 and z0 < z1.
struct FloorWindow {
    double x0 = -0.5, z0 = -0.5, x1 = 0.5, z1 = 0.5;
};

struct PovrayOptions {
    FloorWindow window;
    uint32_t mesh_cells = 0;       // surface cells per side of the water mesh; 0: water.grid_resolution
    double photon_spacing = 0.01;  // m between photons across the beam
    double gather_radius = 0.0;    // m; 0: POV-Ray's automatic (adaptive) radius
};

// A square window of side `side` m around the middle of the floor that lies under the water
// and receives the sun through its surface (for flat water the water's square [-E, E]^2 and
// that square shifted along the refracted beam overlap there): halfway along the shift.
// Its photons neither leave through a wall nor enter near the surface's rim.
FloorWindow lit_floor_window(const Scene& scene, double side);

// The transmittance of the camera's 1 mm of water above the floor, exp(-sigma_t 1e-3) per
// channel: divide a pixel by it to get the irradiance.
glm::dvec3 camera_transmittance(const Scene& scene);

// The POV-Ray scene text. Throws UserError (naming the scene file, the field and what is
// accepted) for a scene without water, with receivers (not exported), with the floor not
// under the water, or for options out of range.
std::string povray_floor_scene(const Scene& scene, const PovrayOptions& options);

}  // namespace vkw::pov
