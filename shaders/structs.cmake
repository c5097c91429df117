# The C++ mirrors of the shaders' push-constant and uniform blocks (tools/shader_structs; docs/architecture.md,
# "Generated mirrors of GLSL blocks"): one header for every shader compiled above, the union of the blocks
# its variants declare (a shader without a block gets an empty namespace). A pass links
# vkwater_shader_structs and includes <shader_structs/<path>.hpp>. Left out: tests/shader_structs_refused.comp,
# whose block the generator must refuse (tests/shader_structs). The structs of common/shared_blocks.comp are
# one C++ type in every header (an alias there), so that one struct fills the same block of many shaders.
vkwater_shader_structs(TARGET vkwater_shader_structs
  DEPENDS vkwater_shaders vkwater_shaders_caustics_bench
  SHARED common/shared_blocks.comp
  EXCLUDE tests/shader_structs_refused.comp)
