// The "floor" section of the scene schema: a horizontal Lambertian square.
#include "engine/scene/scene_json.hpp"

namespace vkw {

FloorPlane read_floor(FieldReader& fields) {
    const FloorPlane defaults;
    FloorPlane floor;
    floor.height = fields.number("height", Range::length(), defaults.height);
    floor.albedo = fields.vec3("albedo", Range::closed(0.0, 1.0), defaults.albedo);
    floor.half_extent = fields.number("half_extent", Range::positive_length(), defaults.half_extent);
    return floor;
}

}  // namespace vkw
