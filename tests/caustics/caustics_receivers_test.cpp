// Caustics on receiver meshes: a tilted plane and a sphere under flat water, the
// photons traced against the sun shadow map's beam half (shaders/caustics/caustic_receiver_hit.glsl)
// and read back with the receiver's own normal. docs/model.md section 3 gives the closed form
//   E = E_perp max(0, -t.N) exp(-sigma_t l),  E_perp = E_s T cos(theta_s) / cos(theta_t),
// l the path from the surface along the refracted sun t. Checked where the receiver point faces
// the beam with -t.N >= 0.25 (the band the test asserts on: nearer the terminator the texels around a point
// hold photons that hit other surfaces) and lies at least 3 texels inside the plane's edges.
// The plane is read through the GLSL lookup (caustic_lookup.glsl, a probe lattice on the plane);
// the sphere, whose normal changes from point to point, by the same bilinear lookup on the CPU
// over the resolved map read back.
#include "engine/scene/scene_loader.hpp"
#include "tests/caustics/caustics_support.hpp"
#include "tests/support/gpu_test.hpp"

#include <cstdio>

namespace vkw::test {
namespace {

constexpr double kE = 3.0, kFloor = -3.0;
constexpr uint32_t kR = 192;  // texel = cell = 2 E / R = 3.125 cm
constexpr double kLevel = 0.0;
const glm::dvec3 kSphereCentre{-0.6, -1.3, -0.4};
constexpr double kSphereRadius = 0.5;

using caustics_receivers = GpuTest;

TEST_F(caustics_receivers, TiltedPlaneAndSphereUnderFlatWaterMatchSection3) {
    const Scene scene = parse_scene(R"({
      "camera": {"position": [0, 5, 6], "target": [0, -1, 0]},
      "sun": {"elevation_deg": 55, "azimuth_deg": 30, "irradiance": [1, 2, 0.5]},
      "sky": {"radiance": [0.2, 0.3, 0.4]},
      "floor": {"height": -3, "half_extent": 3},
      "receivers": [
        {"type": "sphere", "radius": 0.5, "translation": [-0.6, -1.3, -0.4]},
        {"type": "plane", "half_size": [0.5, 0.5], "translation": [0.9, -1.7, 0.6], "rotation_deg": [25, 0, 30]}
      ]
    })",
                                    "receivers.json");
    const passes::ReceiverMeshes meshes(context(), scene.receivers);

    passes::WaterSurfaceInputs surface;
    surface.level = kLevel;
    surface.half_extent = kE;
    surface.grid_resolution = kR;
    passes::CausticInputs in;
    in.sun_direction = scene.sun.direction;
    in.sun_irradiance = scene.sun.irradiance;
    in.ior = 1.333;
    in.sigma_t = {0.06, 0.02, 0.01};
    in.floor_height = kFloor;
    in.map_width = in.map_height = kR + 2;
    in.grid_resolution = kR;
    in.water_level = kLevel;
    in.half_extent = kE;
    const passes::CausticMapFrame frame = passes::fit_caustic_map(in);
    const glm::dvec3 t = frame.direction;
    const double cos_s = -in.sun_direction.y, cos_t = -t.y;
    const glm::dvec3 e_perp = in.sun_irradiance * fresnel_t(cos_s, in.ior) * cos_s / cos_t;
    const auto expected = [&](const glm::dvec3& p, const glm::dvec3& n) {
        return e_perp * std::max(0.0, -glm::dot(t, n)) * glm::exp(-in.sigma_t * (-p.y / cos_t));
    };

    // The plane: its mesh's corners and normal (world space), a lattice from 3 texels inside its
    // edges (the texel's size along the plane is at most texel / |t.N| <= 4 texels of map).
    const Mesh& plane = scene.receivers[1].mesh;
    const glm::dvec3 normal = glm::normalize(glm::dvec3(plane.normals[0]));
    ASSERT_GE(-glm::dot(t, normal), 0.25) << "the plane must face the beam";
    // The plane's own axes: its edges from the first corner (a quad of two triangles).
    const glm::dvec3 c0(plane.positions[plane.indices[0]]);
    glm::dvec3 edge_a(0.0), edge_b(0.0);
    for (const glm::vec3& v : plane.positions) {
        const glm::dvec3 d = glm::dvec3(v) - c0;
        const double len = glm::length(d);
        if (len < 1e-9) continue;
        if (glm::length(edge_a) < 1e-9)
            edge_a = d;
        else if (std::abs(glm::dot(glm::normalize(d), glm::normalize(edge_a))) < 1e-6)
            edge_b = d;
    }
    ASSERT_GT(glm::length(edge_b), 0.5) << "the plane's corners";
    const double inset = 3.0 * frame.texel.x / 0.25 / glm::length(edge_a);  // 3 texels along the plane, as a fraction
    ProbeGrid probes;
    probes.count_x = probes.count_z = 9;
    probes.corner = c0 + inset * edge_a + inset * edge_b;
    probes.step_x = (1.0 - 2.0 * inset) / 8.0 * edge_a;
    probes.step_z = (1.0 - 2.0 * inset) / 8.0 * edge_b;
    probes.normal = normal;
    const CausticRun run = run_caustics(context(), surface, in, probes, &meshes, 3.0);
    EXPECT_EQ(run.lost(0) + run.lost(1) + run.lost(2), 0u);

    // Tolerance, relative, per channel c (the photons all travel along t, so each texel holds
    // exactly the one photon that entered above its centre; only its path length l can differ
    // from the point's):
    // - the beam half's depth is the mesh at a shadow texel's centre, up to sqrt(2)/2 of a shadow
    //   texel across the beam from the photon's column, where a face tilted by theta from the
    //   beam's normal lies that times tan(theta) deeper or shallower (tan(theta) <= sqrt(15) at
    //   -t.N >= 0.25): sigma_c dl;
    // - the bilinear lookup between four texel centres of exp(-sigma_c l): second order,
    //   texel^2 / 8 per axis times sigma_c |d2l/dx2| plus (sigma_c dl/dx)^2; on the sphere
    //   d2l/dx2 <= 1 / (r cos^3 theta) = 128 / m at cos = 0.25 (the plane: 0), dl/dx <= tan(theta);
    // - the facets of the 48 x 24 sphere: its surface lies up to r (1 - cos(pi / 48)) inside the
    //   sphere, along the beam that over cos theta: sigma_c times it;
    // - fp32: the flat-water derivation of caustics_flat_test.cpp, (30 + 10 sigma l) u + 8 delta +
    //   7 u with delta the coordinate rounding in texels, below 2e-4 here (its printed bound).
    const double shadow_texel = passes::fit_sun_shadow(caustic_shadow_inputs(in, meshes, 3.0, kLevel)).beam.params[0];
    const double tan_max = std::sqrt(15.0);
    const double h = frame.texel.x;
    const double sigma_max = std::max({in.sigma_t.x, in.sigma_t.y, in.sigma_t.z});
    const double depth_term = sigma_max * (std::sqrt(0.5) * shadow_texel * tan_max);
    const double fp32_term = 2e-4;
    const double plane_tolerance = depth_term + h * h / 4.0 * std::pow(sigma_max * tan_max, 2) + fp32_term;
    const double sphere_tolerance = plane_tolerance + h * h / 4.0 * sigma_max * 128.0 +
                                    sigma_max * kSphereRadius * (1.0 - std::cos(3.14159265358979 / 48.0)) / 0.25;

    double plane_worst = 0.0;
    for (uint32_t k = 0; k < probes.count_x * probes.count_z; ++k) {
        const glm::dvec3 p =
            probes.corner + double(k % probes.count_x) * probes.step_x + double(k / probes.count_x) * probes.step_z;
        const glm::dvec3 want = expected(p, normal);
        for (int c = 0; c < 3; ++c) {
            const double error = std::abs(run.probes[4 * k + c] / want[c] - 1.0);
            plane_worst = std::max(plane_worst, error);
            EXPECT_LE(error, plane_tolerance)
                << "plane probe " << k << " channel " << c << ": " << run.probes[4 * k + c] << " vs " << want[c];
        }
    }

    // The sphere: points on a latitude-longitude lattice facing the beam.
    const auto map_value = [&](const glm::dvec3& p, int c) {
        const glm::dvec2 at = (glm::dvec2(p.x, p.z) + (p.y - kLevel) * frame.shear - frame.corner) / frame.texel - 0.5;
        const glm::ivec2 base(std::floor(at.x), std::floor(at.y));
        const glm::dvec2 f = at - glm::dvec2(base);
        const auto texel = [&](int x, int y) { return double(run.irradiance[4 * (size_t(y) * frame.width + x) + c]); };
        return glm::mix(glm::mix(texel(base.x, base.y), texel(base.x + 1, base.y), f.x),
                        glm::mix(texel(base.x, base.y + 1), texel(base.x + 1, base.y + 1), f.x), f.y);
    };
    double sphere_worst = 0.0;
    int checked = 0;
    for (int i = 0; i < 40; ++i) {
        for (int j = 0; j < 80; ++j) {
            const double polar = 3.14159265358979 * (i + 0.5) / 40.0, azimuth = 2.0 * 3.14159265358979 * j / 80.0;
            const glm::dvec3 n(std::sin(polar) * std::cos(azimuth), std::cos(polar),
                               std::sin(polar) * std::sin(azimuth));
            // Facing the beam (-t.N >= 0.25), and far enough inside the sphere's outline in the map
            // that the bilinear lookup's four texels all hold photons that hit the sphere: a point
            // at sin(phi) = -t.N lies r (1 - cos(phi)) inside the outline, and the taps reach 1.5
            // texels from it (plus half a texel for the texel centre's own column): 2 texels. With
            // r = 0.5 m and 3.125 cm texels that is -t.N >= 0.48: the band between the terminator and
            // it is the documented edge band of a light-space map.
            const double facing = -glm::dot(t, n);
            if (facing < 0.25 || kSphereRadius * (1.0 - std::sqrt(1.0 - facing * facing)) < 2.0 * frame.texel.x)
                continue;
            const glm::dvec3 p = kSphereCentre + kSphereRadius * n;
            const glm::dvec3 want = expected(p, n);
            ++checked;
            for (int c = 0; c < 3; ++c) {
                const double got = map_value(p, c) * std::max(0.0, -glm::dot(t, n));
                const double error = std::abs(got / want[c] - 1.0);
                sphere_worst = std::max(sphere_worst, error);
                EXPECT_LE(error, sphere_tolerance) << "sphere point " << p.x << ", " << p.y << ", " << p.z
                                                   << " channel " << c << ": " << got << " vs " << want[c];
            }
        }
    }
    EXPECT_GT(checked, 500);
    std::printf(
        "[ figures  ] plane: worst relative error %.2e (tolerance %.2e); sphere: %d points, worst %.2e "
        "(tolerance %.2e)\n",
        plane_worst, plane_tolerance, checked, sphere_worst, sphere_tolerance);
}

}  // namespace
}  // namespace vkw::test
