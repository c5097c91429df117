// The "floor" section of the scene schema: a horizontal Lambertian square, optionally tiled.
#include "engine/scene/scene_json.hpp"

namespace vkw {
namespace {

FloorTiles read_tiles(FieldReader& fields) {
    const FloorTiles defaults;
    FloorTiles tiles;
    tiles.side = fields.number("side", Range::closed(0.001, 100.0, "m"), defaults.side);
    tiles.grout = fields.number("grout", Range::closed(0.0, 100.0, "m"), defaults.grout);
    if (tiles.grout >= tiles.side) {
        fields.fail("grout",
                    format_number(tiles.grout) + " m is not below the tiles' side " + format_number(tiles.side) + " m",
                    "0 <= grout < side");
    }
    tiles.grout_albedo = fields.vec3("grout_albedo", Range::closed(0.0, 1.0), defaults.grout_albedo);
    return tiles;
}

}  // namespace

FloorPlane read_floor(FieldReader& fields) {
    const FloorPlane defaults;
    FloorPlane floor;
    floor.height = fields.number("height", Range::length(), defaults.height);
    floor.albedo = fields.vec3("albedo", Range::closed(0.0, 1.0), defaults.albedo);
    floor.half_extent = fields.number("half_extent", Range::positive_length(), defaults.half_extent);
    if (fields.has("tiles")) floor.tiles = fields.object("tiles", Presence::optional, read_tiles);
    return floor;
}

}  // namespace vkw
