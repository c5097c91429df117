// The "water" section of the scene schema: the surface's placement, optics and grid, and its
// waves (waves_json.cpp).
#include "engine/scene/scene_json.hpp"

namespace vkw {

Water read_water(FieldReader& fields) {
    const Water defaults;
    Water water;
    water.level = fields.number("level", Range::length(), defaults.level);
    // Below 1, total internal reflection would occur above the surface (docs/model.md section 1).
    water.ior = fields.number("ior", Range::closed(1.0, 2.0), defaults.ior);
    const std::optional<double> half_extent =
        fields.number_or_word("half_extent", Range::positive_length(), "infinite", defaults.half_extent);
    water.infinite = !half_extent;
    water.half_extent = half_extent.value_or(defaults.half_extent);  // infinite: set from the receivers
    // Only the schema's range here: what the device can hold is checked by the renderer.
    water.grid_resolution = static_cast<uint32_t>(
        fields.integer("grid_resolution", Range::closed(2.0, 4096.0, "cells per side"), defaults.grid_resolution));
    if (const auto mesh = fields.optional_integer("mesh_resolution", Range::closed(2.0, 4096.0, "cells per side"))) {
        if (water.infinite) {
            fields.fail("mesh_resolution", "a uniform mesh over a square cannot cover infinite water",
                        "leave it out (infinite water is drawn from the screen's grid, mesh_cell_pixels), or give "
                        "half_extent a number");
        }
        water.mesh_resolution = static_cast<uint32_t>(*mesh);
    }
    if (const auto cell = fields.optional_integer("mesh_cell_pixels", Range::closed(1.0, 64.0, "pixels"))) {
        if (water.mesh_resolution) {
            fields.fail("", "both mesh_resolution and mesh_cell_pixels are given",
                        "at most one of mesh_resolution (a uniform mesh), mesh_cell_pixels (the screen's)");
        }
        water.mesh_cell_pixels = static_cast<uint32_t>(*cell);
    }
    water.time = fields.number("time", Range::any("s"), defaults.time);
    water.depth = fields.optional_number("depth", Range::positive_length());
    const auto seed =
        fields.integer("seed", Range::closed(0.0, kMaxExactInteger), static_cast<int64_t>(defaults.waves.seed));
    water.waves = fields.object("waves", Presence::optional, read_waves);
    water.waves.seed = static_cast<uint64_t>(seed);
    return water;
}

}  // namespace vkw
