// Light transport of the model (docs/model.md section 1), in double precision: view rays
// from the air or from the water, one reflection and one refraction at the surface
// (exact Fresnel, total internal reflection, radiance scaled by n^2 entering and 1/n^2
// leaving), Lambertian receivers lit by the shadowed sun and by skylight, sigma_t
// attenuation and single scattering of the refracted sun beam.
//
// Flat water: everything in closed form; the sun under the water is the flat surface's
// refracted beam, shadowed along it, which for flat water is the caustic irradiance.
// Wavy water (a sum of sines and Gerstner waves): the view ray's crossing is bracketed
// along the ray at steps of 1/64 of the shortest wavelength (horizontally) and bisected
// to 1e-12 m, with the exact normal; the floor's sun irradiance is the beam-mapped
// caustic map of floor_caustics.hpp; with receiver meshes under the waves, every receiver's
// (the floor's too) comes from the beams of beam_irradiance.hpp at its points, shadowed by
// the meshes. The in-scatter along view rays follows the caustics too with
// Quality::caustic_in_scatter (caustic_in_scatter.hpp, with the approximations it states; not
// shadowed by meshes, as the flat in-scatter is not), else the flat surface's beam.
// The FFT ocean: its series is evaluated through the zero-padded FFT samples and Hermite
// patches of engine/water/sampled_ocean_surface.hpp (a bounded, measured error); the view
// ray's crossing is bracketed by steps of |f| / L (f the ray's height above the surface, L
// its Lipschitz bound from the largest sampled slope, times 1.5) but never shorter than
// 1/64 of the shortest wavelength, then bisected; the floor's caustics come from the
// periodic floor map of one period (floor_caustics.hpp). Refused with a message for now:
// receiver meshes under an FFT ocean.
#pragma once

#include "engine/scene/scene.hpp"
#include "engine/water/surface.hpp"
#include "tools/reference/beam_irradiance.hpp"
#include "tools/reference/bvh.hpp"
#include "tools/reference/caustic_in_scatter.hpp"
#include "tools/reference/floor_caustics.hpp"

#include <glm/glm.hpp>

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace vkw::ref {

struct PixelRadiance {
    glm::dvec3 radiance{0.0};
    glm::dvec3 caustic{0.0};  // sun irradiance on the receiver seen under the water, else 0
    // The single-scattered radiance of the primary ray's path in the water alone, as the camera
    // receives it ((1 - F) / n^2 of it through the surface from above); not the in-scatter on the
    // paths after a reflection under the surface. 0 where the ray never enters the water.
    glm::dvec3 in_scatter{0.0};
    // Where `caustic` was read: the receiver point under the water that the primary path
    // meets (through the surface from above, or straight in the water); unset when the path
    // sees no receiver under the water. For the pixel footprint (pixel_footprint.hpp).
    std::optional<glm::dvec3> caustic_point;
    glm::dvec3 caustic_normal{0.0};  // the receiver's normal there (unit, toward the light's side)
    // `caustic` one level coarser, when Quality::estimate_caustic_resolution asks for it (the
    // floor map's texel or the beams' patch twice as wide; over footprints, the beams from half
    // the surface cells per side): the difference estimates the caustics' own error.
    glm::dvec3 caustic_coarser{0.0};
};

class WaterTransport {
public:
    // How finely wavy water's floor caustics are computed.
    struct Quality {
        uint32_t floor_texels = 2048;  // texels per side of the floor's caustic map
        double cells_per_wavelength =
            32.0;  // surface cells per shortest wavelength (coarse map; the fine one doubles it)
        // The FFT ocean: the padding of its sampled series (sampled_ocean_surface.hpp), and its
        // periodic floor map's texels and (coarse) surface cells per period.
        uint32_t ocean_padding = 4;
        uint32_t ocean_floor_texels = 1024;
        uint32_t ocean_cells_per_period = 4096;
        // Under waves, the in-scatter modulated by the caustics (caustic_in_scatter.hpp, the
        // model's godrays); off: the flat surface's beam (section 6's closed form), what the
        // real-time renderer computes without its godray passes (the tests that compare the two
        // that way keep it off; `vkwater reference` turns it on).
        bool caustic_in_scatter = false;
        // The in-scatter's planes under waves: how many, their maps'
        // texels per side (over the floor, or per period for the FFT ocean) and surface cells
        // (per shortest wavelength, or per period for the FFT ocean).
        uint32_t in_scatter_levels = 16;
        uint32_t in_scatter_texels = 512;
        double in_scatter_cells_per_wavelength = 16.0;
        uint32_t ocean_in_scatter_texels = 1024;
        uint32_t ocean_in_scatter_cells = 1024;
        // Off: the view rays' geometry alone (no caustic map, no beams, no in-scatter planes;
        // the sun under wavy water then follows the flat surface's beam), for measuring where
        // the pixels land before the maps are sized.
        bool caustics = true;
        // Also read each primary path's caustic one level coarser (PixelRadiance::caustic_coarser;
        // the floor map needs an even floor_texels).
        bool estimate_caustic_resolution = false;
        // Wavy water (not the FFT ocean): every receiver, the floor too, takes its caustics
        // from the beams, averaged over the footprint that trace_camera_ray is given (a share of
        // its pixel) instead of a fixed texel; where none is given, over the floor map's texel.
        bool caustics_over_footprints = false;
    };

    // Throws UserError when the scene needs what this class does not compute.
    explicit WaterTransport(const Scene& scene) : WaterTransport(scene, Quality{}) {}
    WaterTransport(const Scene& scene, const Quality& quality);
    ~WaterTransport();

    // Estimated remaining error of the floor caustics (relative RMS change on refinement);
    // 0 for flat water, where they are closed form.
    double caustic_refinement_change() const { return caustic_refinement_change_; }
    // The approximations this scene's image keeps, one sentence each (for the manifest).
    const std::vector<std::string>& approximations() const { return approximations_; }
    // The FFT ocean's sampled series: the bound on its error in height (m) and in slope
    // (sampled_ocean_surface.hpp); 0 for other surfaces.
    double surface_height_error_bound() const { return surface_height_error_bound_; }
    double surface_slope_error_bound() const { return surface_slope_error_bound_; }
    // The side over which the caustics under wavy water are averaged, m: the floor map's
    // texel, or the beams' patch under meshes; 0 where they are closed form.
    double caustic_texel() const;

    // `footprint`: the part of the receiver the ray stands for (a pixel's stratum), over which
    // the caustics it sees are averaged under Quality::caustics_over_footprints.
    PixelRadiance trace_camera_ray(const Ray& ray, const BeamIrradiance::Patch* footprint = nullptr) const;

    // The model's quantities, exposed for tests.
    bool in_water(const glm::dvec3& point) const;
    glm::dvec3 sun_irradiance_under_water(const glm::dvec3& point, const glm::dvec3& normal,
                                          const BeamIrradiance::Patch* footprint = nullptr) const;
    // The same one level coarser (PixelRadiance::caustic_coarser); closed forms unchanged.
    glm::dvec3 sun_irradiance_one_level_coarser(const glm::dvec3& point, const glm::dvec3& normal,
                                                const BeamIrradiance::Patch* footprint) const;
    // What "one level coarser" is for this scene's caustics, for the manifest ("" if closed form).
    std::string coarser_caustics() const;
    struct WaterHit {
        double distance;
        glm::dvec3 normal;  // unit, toward the air
    };
    // Where the ray crosses the water's surface within its extent (for infinite water, out to
    // the far field, and beyond it the flat level), if it does.
    std::optional<WaterHit> water_surface_hit(const Ray& ray) const;

private:
    struct SurfaceHit {
        double distance;
        glm::dvec3 albedo;
        glm::dvec3 normal;
    };
    std::optional<SurfaceHit> closest_receiver(const Ray& ray, double max_distance) const;
    double surface_height(double x, double z) const;
    // Whether p lies over (or under) the water's square, in x and z; anywhere for infinite water.
    bool over_water(const glm::dvec3& p) const;
    // Radiance arriving along `ray` travelling in air (one surface event already spent
    // or none to come): receivers above the water, or the sky with the sun's disk.
    glm::dvec3 radiance_in_air(const Ray& ray) const;
    // Radiance arriving along `ray` reflected into the air by the water's surface: what
    // radiance_in_air sees, unless the ray meets the true surface again first (a reflection below
    // the horizon, or one that meets the next crest), where it is split again as a camera ray from
    // above is, up to kMaxSurfaceBounces surface events (docs/model.md section 1, "Surface events
    // along a path").
    glm::dvec3 radiance_reflected_into_air(const Ray& ray, int bounces) const;
    // The split at a water surface point `p` (normal `up`) met from the air along `direction`:
    // reflected into the air (radiance_reflected_into_air) and refracted into the water. The
    // camera's ray passes `pixel` for its layers; later bounces pass nullptr.
    glm::dvec3 radiance_from_air_at_surface(const glm::dvec3& p, const glm::dvec3& up, const glm::dvec3& direction,
                                            int bounces, PixelRadiance* pixel,
                                            const BeamIrradiance::Patch* footprint) const;
    // Radiance of a Lambertian receiver point, in air or under the water.
    // `primary`, when given, receives the point's sun irradiance under the water as the
    // pixel's caustic layer, and the point.
    glm::dvec3 receiver_radiance(const glm::dvec3& point, const SurfaceHit& hit, PixelRadiance* primary,
                                 const BeamIrradiance::Patch* footprint = nullptr) const;
    // Radiance arriving at `start` along `ray` inside the water, up to the receiver it
    // meets (a ray in the water meets the surface no more); its in-scatter
    // alone also in `in_scatter`, when given.
    glm::dvec3 radiance_in_water_to_receiver(const Ray& ray, PixelRadiance* primary, glm::dvec3* in_scatter = nullptr,
                                             const BeamIrradiance::Patch* footprint = nullptr) const;
    // Radiance arriving at `origin` in the water along `direction` over `length`, `behind` at
    // its far end: attenuation and in-scatter (closed form under flat water, modulated by the
    // caustics under waves); the in-scatter term alone also in `in_scatter`, when given.
    glm::dvec3 in_water_segment(const glm::dvec3& origin, double length, const glm::dvec3& direction,
                                const glm::dvec3& behind, glm::dvec3* in_scatter = nullptr) const;
    // How far a ray in infinite water that meets no receiver runs: to the water's bottom, no
    // farther than the far field from its origin, horizontally (docs/model.md section 1); 0 for
    // water with an edge, which such a ray leaves through the side, and for a ray not pointing down.
    double run_to_bottom(const Ray& ray) const;
    bool sun_blocked_in_air(const glm::dvec3& point) const;
    BeamIrradiance::Visibility beam_visibility() const;
    bool meshes_under_water() const;  // any receiver mesh reaching below the highest crest
    // The FFT ocean's sampled surface, its crossing slope and its periodic floor caustics.
    void build_ocean(const Quality& quality);
    // Relative RMS change of the receivers' sun irradiance from `coarse` to the beams in use
    // (RMS over the mean, the worst 0.1% of points dropped).
    double estimate_beam_refinement(const BeamIrradiance& coarse) const;

    const Scene& scene_;
    std::vector<Mesh> extra_meshes_;  // the floor as a mesh
    // Per receiver index of the BVH, its mesh and its triangles' albedo by index range
    // (receiver_albedo_parts).
    std::vector<const Mesh*> meshes_;
    std::vector<std::vector<MeshPart>> albedo_parts_;
    // The base colour (RGB: the Lambertian albedo; and alpha) at barycentric (u, v) of triangle
    // `triangle` of mesh `receiver`: the part's factor times its texture and the vertex colour there.
    glm::dvec4 base_color_at(uint32_t receiver, uint32_t triangle, const glm::dvec2& barycentric) const;
    // Whether that point is cut out of its mesh (a cutout part's alpha below its cutoff).
    bool cut_out(uint32_t receiver, uint32_t triangle, const glm::dvec2& barycentric) const;
    const MeshPart& part_of(uint32_t receiver, uint32_t triangle) const;
    std::unique_ptr<TriangleBvh> bvh_;
    double level_ = 0.0, half_extent_ = 0.0, bottom_ = 0.0, ior_ = 1.0;
    bool has_water_ = false;
    // Infinite water (docs/model.md section 1, "Infinite water"): no edge, and beyond
    // kInfiniteWaterFarField from a ray's origin the flat mean level.
    bool infinite_ = false;
    std::unique_ptr<WaterSurface> surface_;  // wavy water only
    // Steps along view rays: |f| / (|d_y| + |d_h| crossing_slope_) when crossing_slope_ > 0
    // (the FFT ocean), else the fixed step of 1/64 of the shortest wavelength.
    double crossing_slope_ = 0.0;
    std::vector<std::string> approximations_;
    double surface_height_error_bound_ = 0.0, surface_slope_error_bound_ = 0.0;
    std::unique_ptr<FloorCausticMap> floor_caustics_;  // wavy water over the floor alone
    std::unique_ptr<BeamIrradiance> beams_;            // wavy water with meshes under it, or over footprints
    std::unique_ptr<BeamIrradiance> coarser_beams_;    // over footprints: half the cells, for the estimate
    std::unique_ptr<CausticInScatter> in_scatter_;     // wavy water: the godrays
    double caustic_refinement_change_ = 0.0;
    bool estimate_caustic_resolution_ = false;
    double shortest_wavelength_ = 0.0;
    double max_amplitude_ = 0.0;
    bool sun_up_ = false;
    glm::dvec3 refracted_sun_{0.0, -1.0, 0.0};  // t, unit, downward
    glm::dvec3 e_perp0_{0.0};                   // E_s cos(theta_s) T / cos(theta_t), per channel
    glm::dvec3 sky_average_{0.0};
    double hemispherical_transmittance_ = 1.0;
    double sun_disk_cos_ = 1.0;
};

}  // namespace vkw::ref
