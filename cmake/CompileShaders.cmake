# Compiles GLSL to SPIR-V in the build tree with glslangValidator. The depfile makes an
# edit to an included .glsl rebuild every shader that includes it. A shader error fails
# the build with glslang's file:line message.

# The one compile rule: `abs` (a source under shaders/) to `out` with extra arguments.
function(vkwater_glsl_command abs out)
  file(RELATIVE_PATH rel ${CMAKE_SOURCE_DIR}/shaders ${abs})
  get_filename_component(out_dir ${out} DIRECTORY)
  add_custom_command(
    OUTPUT ${out}
    COMMAND ${CMAKE_COMMAND} -E make_directory ${out_dir}
    COMMAND Vulkan::glslangValidator --quiet --target-env vulkan1.3 ${ARGN}
            -I${CMAKE_SOURCE_DIR}/shaders
            --depfile ${out}.d -o ${out} ${abs}
    MAIN_DEPENDENCY ${abs}
    DEPFILE ${out}.d
    COMMENT "GLSL ${out}"
    VERBATIM)
endfunction()

# vkwater_compile_shaders(TARGET name SOURCES a.comp b.frag ...): build/shaders/<path>.spv each.
function(vkwater_compile_shaders)
  cmake_parse_arguments(ARG "" "TARGET" "SOURCES" ${ARGN})
  set(outputs)
  foreach(src IN LISTS ARG_SOURCES)
    get_filename_component(abs ${src} ABSOLUTE)
    file(RELATIVE_PATH rel ${CMAKE_SOURCE_DIR}/shaders ${abs})
    set(out ${VKWATER_SHADER_OUTPUT_DIR}/${rel}.spv)
    vkwater_glsl_command(${abs} ${out})
    list(APPEND outputs ${out})
  endforeach()
  add_custom_target(${ARG_TARGET} ALL DEPENDS ${outputs})
endfunction()

# vkwater_compile_shader_variants(TARGET name SOURCE file VARIANTS variant=DEF1,DEF2 ...)
# Compiles one GLSL source once per variant with those macros defined, into
# build/shaders/<path>.<variant>.spv; the engine loads it as "<path>.<variant>". The
# permutations of a shader (per-pixel camera medium, caustics, shadows) then live in one file.
function(vkwater_compile_shader_variants)
  cmake_parse_arguments(ARG "" "TARGET;SOURCE" "VARIANTS" ${ARGN})
  get_filename_component(abs ${ARG_SOURCE} ABSOLUTE)
  file(RELATIVE_PATH rel ${CMAKE_SOURCE_DIR}/shaders ${abs})
  set(outputs)
  foreach(variant IN LISTS ARG_VARIANTS)
    string(REPLACE "=" ";" parts "${variant}")
    list(GET parts 0 name)
    set(defines)
    list(LENGTH parts count)
    if(count GREATER 1)
      list(GET parts 1 macros)
      string(REPLACE "," ";" macros "${macros}")
      foreach(macro IN LISTS macros)
        list(APPEND defines -D${macro})
      endforeach()
    endif()
    set(out ${VKWATER_SHADER_OUTPUT_DIR}/${rel}.${name}.spv)
    vkwater_glsl_command(${abs} ${out} ${defines})
    list(APPEND outputs ${out})
  endforeach()
  add_custom_target(${ARG_TARGET} ALL DEPENDS ${outputs})
endfunction()
