# The C++ mirrors of the shaders' push-constant and uniform blocks (tools/shader_structs; docs/architecture.md,
# "Generated mirrors of GLSL blocks"): every shader stage file above that declares such a block. A pass
# links vkwater_shader_structs and includes <shader_structs/<path>.hpp>. A shader compiled in variants is
# read in the variant that declares the most blocks (the blocks the others declare are the same).
# Left out: the shaders without a block (common/fullscreen.vert, common/calibration.frag,
# tests/gradient.comp, tests/copy_texels.frag) and tests/shader_structs_refused.comp, whose block the
# generator must refuse (tests/shader_structs). The structs of common/shared_blocks.comp are one C++
# type in every header (an alias there), so that one struct fills the same block of many shaders.
vkwater_shader_structs(TARGET vkwater_shader_structs
  DEPENDS vkwater_shaders vkwater_shaders_caustics_bench
  SHARED common/shared_blocks.comp
  SHADERS
  common/shared_blocks.comp
  receivers/floor.vert
  receivers/mesh.vert
  receivers/receiver.frag.per_pixel_caustics_shadow_mesh_layer
  receivers/sun_shadow.vert
  receivers/sun_shadow.frag.cutout
  water/scene_optics.comp
  water/water_surface.vert
  water/water_surface.frag.per_pixel_caustics_shadow_views_layer
  water/camera_medium_mask.frag
  water/wave_sum.comp
  water/ocean_spectra.comp
  water/ocean_fft.comp
  water/ocean_grid.comp
  sky/sky.frag.per_pixel
  caustics/caustic_resolve.comp
  caustics/caustic_camera_resolve.comp
  caustics/caustic_blur.comp
  caustics/caustic_procedural.comp
  caustics/caustic_probe.comp
  caustics/caustic_receivers.frag.cutout
  caustics/caustic_photons.comp.bilinear_shadow
  caustics/caustic_camera_splats.comp.shadow
  caustics/bench/caustic_scatter_fixed.comp
  caustics/bench/caustic_scatter_tile.comp
  caustics/bench/caustic_scatter_float_cas.comp
  caustics/bench/caustic_scatter_float_native.comp
  godrays/godray_lines.comp
  godrays/godray_resolve.comp
  godrays/godray_blur.comp
  godrays/godray_beams.comp.shadow
  godrays/godray_depth.comp.per_pixel
  godrays/godray_composite.frag.layer
  godrays/godray_march.comp.caustics_shadow
  present/present_tonemap.frag
  frame/upscale.frag
  frame/accumulate.comp
  tests/fresnel_sweep.comp
  tests/in_scatter_sweep.comp
  tests/glitter_sweep.comp
  tests/poison.comp
  tests/sky_doubled.frag
  tests/water_refinement_probe.frag
  tests/reflection_probe.comp.plain
  tests/shader_structs_probe.comp
)
