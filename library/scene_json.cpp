// vkwater::scene_json (include/vkwater/scene.hpp): the structs written as a scene file's JSON, field
// for field (scenes/README.md), so that one loader checks files and structs alike.
#include <vkwater/scene.hpp>

#include <nlohmann/json.hpp>

namespace vkwater {
namespace {

using nlohmann::json;

json vec3(const std::array<double, 3>& v) { return json::array({v[0], v[1], v[2]}); }

json camera_json(const Camera& camera) {
    return {{"position", vec3(camera.position)},
            {"target", vec3(camera.target)},
            {"fov_y_deg", camera.fov_y_deg},
            {"near", camera.near_plane},
            {"far", camera.far_plane}};
}

json sky_json(const Sky& sky) {
    if (!sky.gradient) return {{"radiance", vec3(sky.radiance)}};
    json out = {{"model", "gradient"},
                {"zenith", vec3(sky.gradient->zenith)},
                {"horizon", vec3(sky.gradient->horizon)},
                {"exponent", sky.gradient->exponent}};
    if (sky.gradient->ground) out["ground"] = vec3(*sky.gradient->ground);
    return out;
}

json water_json(const Water& water) {
    json out = {{"level", water.level},
                {"ior", water.ior},
                {"half_extent", water.infinite ? json("infinite") : json(water.half_extent)},
                {"grid_resolution", water.grid_resolution},
                {"time", water.time}};
    if (!water.waves.empty()) {
        json components = json::array();
        for (const Wave& wave : water.waves) {
            components.push_back({{"amplitude", wave.amplitude},
                                  {"wavelength", wave.wavelength},
                                  {"direction_deg", wave.direction_deg},
                                  {"phase_deg", wave.phase_deg},
                                  {"steepness", wave.steepness}});
        }
        out["waves"] = {{"model", "sum"}, {"components", components}};
    }
    return out;
}

json medium_json(const Medium& medium) {
    if (!medium.preset.empty()) return {{"preset", medium.preset}};
    return {{"sigma_a", vec3(medium.sigma_a)}, {"sigma_s", vec3(medium.sigma_s)}, {"g", medium.g}};
}

json receiver_json(const Receiver& receiver) {
    json out = {{"albedo", vec3(receiver.albedo)},
                {"translation", vec3(receiver.translation)},
                {"rotation_deg", vec3(receiver.rotation_deg)},
                {"scale", vec3(receiver.scale)}};
    if (!receiver.name.empty()) out["name"] = receiver.name;
    switch (receiver.shape) {
        case Receiver::Shape::Box:
            out["type"] = "box";
            out["half_size"] = vec3(receiver.half_size);
            break;
        case Receiver::Shape::Sphere:
            out["type"] = "sphere";
            out["radius"] = receiver.radius;
            break;
        case Receiver::Shape::Plane:
            out["type"] = "plane";
            out["half_size"] = json::array({receiver.half_size[0], receiver.half_size[2]});
            break;
    }
    return out;
}

}  // namespace

std::string scene_json(const Scene& scene) {
    json out = {{"camera", camera_json(scene.camera)},
                {"sun",
                 {{"elevation_deg", scene.sun.elevation_deg},
                  {"azimuth_deg", scene.sun.azimuth_deg},
                  {"irradiance", vec3(scene.sun.irradiance)}}},
                {"sky", sky_json(scene.sky)},
                {"floor",
                 {{"height", scene.floor.height},
                  {"albedo", vec3(scene.floor.albedo)},
                  {"half_extent", scene.floor.half_extent}}},
                {"medium", medium_json(scene.medium)}};
    if (!scene.description.empty()) out["description"] = scene.description;
    if (scene.water) out["water"] = water_json(*scene.water);
    if (!scene.receivers.empty()) {
        json receivers = json::array();
        for (const Receiver& receiver : scene.receivers) receivers.push_back(receiver_json(receiver));
        out["receivers"] = receivers;
    }
    // A NaN or an infinity is written as null, which the loader refuses naming the field; text that
    // is not UTF-8 (a name, the description) is written with U+FFFD in its place, never a throw.
    return out.dump(2, ' ', false, json::error_handler_t::replace);
}

}  // namespace vkwater
