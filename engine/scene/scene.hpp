// The scene as the renderers see it: camera, sun, sky, floor, water, medium, receivers and
// effect settings, in double precision (the CPU reference renderer works in doubles).
// Units: metres, y up, right-handed; irradiance in W m^-2 and radiance in W m^-2 sr^-1 per RGB
// channel (docs/model.md section 1).
//
// The default member values are the defaults of the optional fields of the scene file
// (scenes/README.md); the loader reads them from here, so they are stated only once.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "engine/scene/builtin_meshes.hpp"
#include "engine/scene/effects.hpp"
#include "engine/scene/medium.hpp"
#include "engine/scene/mesh.hpp"
#include "engine/water/wave_params.hpp"

namespace vkw {

struct Camera {
    glm::dvec3 position{0.0, 0.0, 0.0};  // required in a scene file
    // A point the camera looks at, != position. The file gives either `target` or `direction`;
    // a direction d becomes target = position + d / |d|.
    glm::dvec3 target{0.0, 0.0, -1.0};
    double fov_y_deg = 60.0;   // full vertical field of view, in (1, 179)
    double near_plane = 0.05;  // metres, 0 < near_plane < far_plane
    double far_plane = 500.0;  // metres
    double exposure = 1.0;     // linear scale on radiance before display, > 0
    // A supersampled image's sub-pixel shift of the image plane, in NDC (2 / width per pixel along
    // x; engine/scene/pixel_filter.hpp). Never read from a scene file: 0 is the pixel centres.
    glm::dvec2 image_shift_ndc{0.0, 0.0};
};

struct Sun {
    // Unit vector, the direction the light TRAVELS: y < 0 when the sun is above the horizon.
    // A sun below the horizon (y >= 0) is valid and lights nothing.
    glm::dvec3 direction{0.0, -1.0, 0.0};
    // Irradiance on a plane normal to the beam, W m^-2 per channel. The default of 1 makes
    // radiances read directly as multiples of the sun's irradiance.
    glm::dvec3 irradiance{1.0, 1.0, 1.0};
    // Texels per side of the sun shadow map that receiver meshes cast into (the floor, the
    // caustic photons and the godrays read it): 1024 resolves about 2 cm over a 20 m floor.
    uint32_t shadow_texels = 1024;
};

enum class SkyModel : uint8_t { Constant, Gradient };

// Sky radiance L(dir) in W m^-2 sr^-1 for a unit direction dir (see sky_radiance below).
struct Sky {
    SkyModel model = SkyModel::Constant;
    glm::dvec3 radiance{0.0, 0.0, 0.0};  // Constant: the radiance of every direction; required
    glm::dvec3 zenith{0.0, 0.0, 0.0};    // Gradient: straight up; required
    glm::dvec3 horizon{0.0, 0.0, 0.0};   // Gradient: at the horizon; required
    glm::dvec3 ground{0.0, 0.0, 0.0};    // Gradient: every direction below the horizon; default horizon
    double exponent = 0.5;               // Gradient: > 0, shape of the blend
};

// Horizontal Lambertian plane y = height: a square of side 2 * half_extent centred
// under the origin (x and z in [-half_extent, half_extent]).
// floor.tiles: square tiles of side `side` in x and z, their edges on the multiples of `side`,
// with grout lines `grout` wide centred on the edges. The tiles take the floor's albedo.
struct FloorTiles {
    double side = 0.25;                      // metres, > 0
    double grout = 0.01;                     // metres, 0 <= grout < side
    glm::dvec3 grout_albedo{0.6, 0.6, 0.6};  // in [0, 1] per channel
};

struct FloorPlane {
    double height = -1.5;              // metres; the pool floor 1.5 m below the water level
    glm::dvec3 albedo{0.5, 0.5, 0.5};  // in [0, 1] per channel
    double half_extent = 10.0;         // metres, > 0
    std::optional<FloorTiles> tiles;   // nullopt: one albedo everywhere
    // The albedo at (x, z): the grout's within grout / 2 of a tile edge, the floor's elsewhere
    // (shaders/receivers/floor_albedo.glsl evaluates the same pattern in float).
    glm::dvec3 albedo_at(double x, double z) const;
};

inline constexpr uint32_t kDefaultWaterMeshResolution = 256;

// The screen grid's cell width for infinite water that names no mesh: cells of 8 pixels keep
// Newton's start within a crest of the crossing for the built-in waves (docs/techniques/water_surface.md).
inline constexpr uint32_t kDefaultInfiniteWaterCellPixels = 8;

// Infinite water's far field (docs/model.md section 1, "Infinite water"): beyond this distance
// from the camera both renderers take the surface as its mean level, flat. Waves there are finer
// than a pixel for the cameras the schema allows within a few metres of the water, and a point
// sample of them is aliasing, not detail.
inline constexpr double kInfiniteWaterFarField = 2000.0;  // metres

// The water body: a surface around y = level over the square |x|, |z| <= half_extent, and the
// water volume below it down to level - depth (or to the floor when depth is not given).
// Infinite water (`"half_extent": "infinite"`) has no edge: its surface and volume reach the
// horizon, and half_extent is then the square that holds every receiver (the floor's and the
// meshes'), over which the photons, the godray beams and the reference's maps are traced.
struct Water {
    double level = 0.0;         // metres, mean surface height
    double ior = 1.333;         // index of refraction, in [1, 2] (docs/model.md section 1)
    double half_extent = 10.0;  // metres, > 0
    bool infinite = false;
    // Surface grid cells per side, in [2, 4096]. The device's own limits (buffer sizes,
    // dispatch counts) are checked by the renderer, not here.
    uint32_t grid_resolution = 256;
    // The water is drawn from a mesh, and each pixel then finds the exact surface from the
    // mesh's point (docs/techniques/water_surface.md), so the mesh need not be as fine as the photon grid.
    // By default a uniform mesh over the square (mesh_resolution cells per side, in [2, 4096]);
    // with mesh_cell_pixels (in [1, 64]) a grid that follows the screen instead, with cells about
    // that many pixels wide wherever they are seen. A scene gives at most one.
    std::optional<uint32_t> mesh_resolution;
    std::optional<uint32_t> mesh_cell_pixels;
    // The uniform mesh's cells per side: mesh_resolution, or the smaller of
    // kDefaultWaterMeshResolution and grid_resolution.
    uint32_t drawn_mesh_resolution() const;
    // The screen mesh's cell width in pixels; 0 when the uniform mesh is drawn. Infinite water
    // is always drawn from the screen's grid.
    uint32_t screen_mesh_cell_pixels() const;
    double time = 0.0;            // seconds at which the waves are evaluated
    std::optional<double> depth;  // metres below level, > 0; nullopt: down to the floor
    WaveSettings waves;           // the file's water.seed is waves.seed
};

enum class ReceiverType : uint8_t { Plane, Box, Sphere, Terrain, Gltf };

// A Lambertian object (docs/model.md section 1): the built-in shape or glTF mesh, already
// transformed to world space.
struct Receiver {
    std::string name;  // from the file; default: its field path, "receivers[2]"
    ReceiverType type = ReceiverType::Plane;
    // Lambertian albedo in [0, 1] of the whole mesh where it has no parts: the built-in shapes
    // (default 0.5 grey), and a glTF mesh given an `albedo`, which replaces its materials' base
    // colours. A glTF mesh without one keeps its materials' colours (mesh.parts).
    glm::dvec3 albedo{0.5, 0.5, 0.5};
    glm::dmat4 object_to_world{1.0};  // translation * rotation * scale, as in the file
    Mesh mesh;                        // world space
    // A terrain's shape as the file gives it; its mesh may be drawn coarser (set_terrain_detail).
    std::optional<TerrainShape> terrain;
};

// A terrain receiver's cells per side at `fraction` of the file's (at least 2, the schema's least).
uint32_t terrain_cells(const TerrainShape& shape, double fraction);

// Rebuilds a terrain receiver's mesh at `fraction` of its file's cells per side (1: the file's
// own), for the frame-time budget's receiver-detail knob; nothing for other receivers or where the
// mesh already has that many cells.
void set_terrain_detail(Receiver& receiver, double fraction);

// The receiver's triangles grouped by their Lambertian albedo, as both renderers shade them: the
// mesh's material parts, or one part of `albedo` over every index.
std::vector<MeshPart> receiver_albedo_parts(const Receiver& receiver);

// effects.<name>.mode: auto lets the frame's needs decide; on and off force the decision.
enum class EffectMode : uint8_t { Auto, On, Off };

// How the water shading finds the scene's objects along reflected and refracted rays
// (effects.reflection.method, effects.refraction.method; passes/scene_views/scene_view.hpp).
enum class SceneLookup : uint8_t {
    Projective,   // the estimated hit, refined by fixed-point steps (de la Fuente 2011 and Optical Phenomena c. 2008)
    ScreenSpace,  // a ray march through the view's depth, then bisection (Ojeda & Susín 2013)
};

struct EffectSettings {
    EffectMode mode = EffectMode::Auto;
    // reflection and refraction only: the method and its number of steps
    SceneLookup method = SceneLookup::Projective;
    int max_steps = 64;
    // refraction, screen-space only: Ojeda & Susín 2013's blend to the direct view where less than this
    // much water (m, along the view ray) lies over what is behind; 0: off (the exact default)
    double shallow_blend = 0.0;
};

// One entry per Effect (engine/scene/effects.hpp), indexed by the enum (CausticBlur is its last value).
inline constexpr std::size_t kEffectCount = kAllEffects.size();

// effects.godrays.method: how the in-scatter of the sun's beams under the water is computed
// (passes/godrays/godrays.hpp).
enum class GodrayMethod : uint8_t {
    Lines,    // each photon's beam walked as a line over the pixels it crosses (de la Fuente 2011 section 4.6)
    Marched,  // the baseline: each view ray marched through the water
};

// The settings of effects.godrays beside its mode (scenes/README.md).
struct GodraySettings {
    uint32_t grid = 64;               // photon beams per side over the water, in [2, 1024]
    double resolution_scale = 0.5;    // of the output size: 1 or 0.5
    std::optional<double> max_depth;  // m below the mean level where beams stop; nullopt: at the floor
    GodrayMethod method = GodrayMethod::Lines;
    uint32_t march_steps = 32;  // Marched: steps per view segment in the water, in [1, 4096]
};

// effects.caustics.kernel: how a photon's flux is splatted into the light-space map.
enum class CausticKernel : uint8_t {
    Bilinear,   // a tent one texel wide: the 2x2 bilinear splat
    Adaptive,   // a tent as wide as the photon's neighbours land apart (1 to 4 texels per axis)
    Footprint,  // the photon's sub-cell's footprint, by area (Tipprasert 2006's area ratio; up to 8 texels per axis)
};

// The kernel's name in scene files (effects.caustics.kernel).
const char* caustic_kernel_name(CausticKernel kernel);

// effects.caustics.method: what produces the caustic map.
enum class CausticMethod : uint8_t {
    Photons,  // the photon grid (passes/caustics/caustics_photons.hpp)
    Procedural,  // Guardado & Sánchez-Crespo 2004's backward ray and sun lobe, a baseline (passes/caustics/caustics_procedural.hpp)
};

// effects.caustics.splat: where the photons' flux is gathered.
enum class CausticSplat : uint8_t {
    LightSpace,  // the light-space map along the refracted sun, read by every receiver (passes/caustics/caustics_photons.hpp)
    CameraSpace,  // gaussians on the receivers the camera sees without the water (Ojeda & Susín 2013;
                  // passes/caustics/caustics_camera_splats.hpp)
};

// The settings of effects.caustics beside its mode (scenes/README.md).
struct CausticSettings {
    CausticMethod method = CausticMethod::Photons;
    // Flat water: the flat-surface stand-in is exact there, so the photon passes are left out
    // unless this is false (then they run and reproduce it up to the map's resolution).
    bool analytic_flat = true;
    uint32_t sub_photons = 1;  // S: S x S photons per cell of the water grid, in [1, 8]
    bool jitter = false;       // each photon at a hashed point of its sub-cell instead of its centre
    // Photons whose kernel reaches no texel the frame can read are left out (the image is the
    // same bit for bit); false keeps every photon.
    bool cull = true;
    CausticKernel kernel = CausticKernel::Adaptive;  // the light-space map's splat
    CausticSplat splat = CausticSplat::LightSpace;
    // The light-space map's texels per water cell along each side, in [0.25, 4]: 1 puts one photon
    // per texel (S = 1) on the texel centres under flat water; more resolves finer caustics with
    // fewer photons per texel (the adaptive kernel then widens to fill), less averages more.
    double map_scale = 1.0;
};

// The settings of effects.caustic_blur beside its mode (scenes/README.md).
struct CausticBlurSettings {
    // r0, texels of the caustic map: the blur's radius where photons are as dense as under flat
    // water; it grows as sqrt(E_flat / E) where they are sparser, up to 4 (passes/caustics/caustics_blur.hpp).
    // 0 (the default): no blur, and the rule leaves the passes out. Measured on pool (docs/techniques/caustics.md): with the adaptive splat kernel any blur adds error (relMSE 0.0489 -> 0.0505 at
    // 0.5); with the bilinear kernel 0.5 helps (0.0572 -> 0.0511).
    double radius = 0.0;
};

// effects.water.fresnel: how the surface splits light between reflection and refraction.
enum class SurfaceFresnel : uint8_t {
    Exact,    // the Fresnel equations (docs/model.md section 2), total internal reflection included
    Schlick,  // Schlick's approximation, taken on the less dense side (common/fresnel.glsl)
    Power,  // Optical Phenomena c. 2008's power term F = (1 - E.N)^q; total internal reflection kept from the exact form
};

// effects.water.depth_blend: Optical Phenomena c. 2008's depth colour, C_w + exp(-k d) (C - C_w), in place of the
// medium's attenuation and in-scatter along refracted rays (d: their path in the water).
struct DepthBlend {
    glm::dvec3 colour{0.0, 0.2, 0.1};  // C_w, as radiance (the paper's table: a display colour)
    double k = 0.5;                    // 1/m (the paper's table)
};

// The settings of effects.water beside its mode: the surface's shading. The defaults are the
// model of docs/model.md section 1; the others are the published approximations, there to be measured.
struct WaterShadingSettings {
    SurfaceFresnel fresnel = SurfaceFresnel::Exact;
    double fresnel_power = 4.5;  // q of the power term, in [1, 10] (the paper's table: 4.5)
    std::optional<DepthBlend> depth_blend;
    // The sun's glitter: the slopes of the waves a pixel cannot resolve as a lobe for the sun's
    // reflection (shaders/water/sun_glitter.glsl) in place of its disk where they spread it more.
    bool glitter = false;
};

struct EffectsSettings {
    WaterShadingSettings water;
    GodraySettings godrays;
    CausticSettings caustics;
    CausticBlurSettings caustic_blur;
    std::array<EffectSettings, kEffectCount> settings{};
    const EffectSettings& operator[](Effect effect) const { return settings[static_cast<std::size_t>(effect)]; }
    EffectSettings& operator[](Effect effect) { return settings[static_cast<std::size_t>(effect)]; }
};

struct Scene {
    std::filesystem::path source;  // the file it was loaded from, as given to the loader
    std::string description;       // free text saying what the scene exercises
    Camera camera;
    Sun sun;
    Sky sky;
    FloorPlane floor;
    std::optional<Water> water;        // nullopt: no water in the scene
    Medium medium = default_medium();  // the water's optical properties
    std::vector<Receiver> receivers;
    EffectsSettings effects;
    // Distinct for every scene the loader makes (copies share it): what the renderer keys its
    // uploaded receiver meshes and textures on, with the scene's address, since a scene loaded
    // anew can reuse a freed one's address. 0 for scenes built in code.
    uint64_t load_id = 0;
};

// What the scene's files ask for that the renderers leave out (the receivers' glTF files: mesh
// warnings), one line each, naming the receiver's field: the commands print them as warnings.
std::vector<std::string> scene_warnings(const Scene& scene);

// Sky radiance toward unit direction `dir`. Constant: sky.radiance. Gradient (scenes/README.md):
//   L = mix(horizon, zenith, pow(dir.y, exponent)) for dir.y >= 0, ground below.
glm::dvec3 sky_radiance(const Sky& sky, const glm::dvec3& dir);

// L_sky_avg of docs/model.md section 1: (1/pi) * integral over the upper hemisphere of
// L cos(theta) d(omega). Constant: radiance; gradient, in closed form:
//   horizon + (zenith - horizon) * 2 / (exponent + 2).
glm::dvec3 sky_average_radiance(const Sky& sky);

// The y of the bottom of the water volume: level - depth, or the floor's height.
double water_bottom(const Scene& scene);
// The half side of the square the water's surface is drawn over: half_extent, or for infinite
// water one that holds every point within the camera's far distance (what the camera can see).
double water_drawn_half_extent(const Scene& scene);
// For infinite water, the square that holds the floor and every receiver mesh (its half_extent).
double receivers_half_extent(const Scene& scene);

// Direction TOWARD the sun for elevation `el` above the horizon and azimuth `az`, both in
// degrees: u = (cos(el) sin(az), sin(el), -cos(el) cos(az)). Azimuth 0 faces -z ("north",
// glTF's default forward), 90 faces +x ("east"). Exact at multiples of 90 degrees, so an
// overhead sun is exactly (0, 1, 0). The sun's travelling direction is -u.
glm::dvec3 direction_toward_sun(double elevation_deg, double azimuth_deg);

// Right-handed world-to-view matrix for the camera, up = +y. When the view direction is
// within about 2.6 degrees of vertical (|dot(dir, +y)| > 0.999) +y cannot define "up", so
// -z (north) is used instead: looking straight down or up, north is at the top of the image.
glm::dmat4 view_matrix(const Camera& camera);

// Reversed-Z perspective projection (depth 1 at the near plane, 0 at the far plane) in
// OpenGL-style y-up clip space, for an output of this width/height ratio. Both
// renderers build their camera rays from view_matrix and this.
glm::dmat4 projection_matrix(const Camera& camera, double aspect);

}  // namespace vkw
