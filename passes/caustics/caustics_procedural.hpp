// Guardado & Sánchez-Crespo 2004's procedural caustic as a baseline (effects.caustics.method = procedural):
// no photons. Each texel of the light-space caustic map (the same frame as the photons', so every
// receiver reads it through the same lookup) takes the point where its line along the flat-water
// refracted sun t crosses the mean level, the water's normal there (the surface grid, bilinear
// between vertices, looked up by grid parameter: no horizontal-displacement inversion), and
// traces Guardado & Sánchez-Crespo 2004's backward ray: up along -t, refracted into the air, compared with the
// direction of the sun. Its irradiance is the flat surface's, E_perp attenuated to the floor,
// times a sun-disk lobe exp(-(theta / 4 degrees)^2) of the angle theta between the refracted ray
// and the sun (Guardado & Sánchez-Crespo 2004's blurred "sun map"; 4 degrees is this baseline's one free parameter).
// Flat water gives theta = 0 everywhere, the stand-in exactly; under waves it only darkens (no
// focusing, no energy conservation): the aesthetic method the seed describes, there to be measured.
#pragma once

#include "engine/framegraph/frame_graph.hpp"
#include "passes/caustics/caustics_light_space.hpp"
#include "passes/caustics/caustics_resolve.hpp"

namespace vkw::passes {

// Reads inputs.surface (the vertex grid of add_water_surface_pass, one binding) and returns the
// map as add_caustic_resolve_pass does.
CausticMap add_caustic_procedural_pass(fg::FrameGraph& graph, const CausticInputs& inputs);

}  // namespace vkw::passes
