# One custom command per shader: glslangValidator compiles shaders/NAME.EXT to
# ${TAA_SHADER_OUT}/NAME.EXT.spv and is re-run when the shader or any header under
# shaders/ changes. The renderer finds SPIR-V by name at run time.
set(TAA_SHADER_OUT ${CMAKE_BINARY_DIR}/shaders)

function(taa_compile_shader src out defines)
  file(GLOB_RECURSE headers CONFIGURE_DEPENDS ${CMAKE_SOURCE_DIR}/shaders/*.glsl
       ${CMAKE_SOURCE_DIR}/shaders/*.h)
  get_filename_component(name ${out} NAME)
  # vulkan1.2 target: vulkan1.3 would emit LocalSizeId, which needs maintenance4.
  add_custom_command(
    OUTPUT ${out}
    COMMAND ${CMAKE_COMMAND} -E make_directory ${TAA_SHADER_OUT}
    COMMAND ${GLSLANG_VALIDATOR} --quiet --target-env vulkan1.2 -I${CMAKE_SOURCE_DIR}/shaders
            ${defines} -o ${out} ${CMAKE_CURRENT_SOURCE_DIR}/${src}
    DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/${src} ${headers}
    COMMENT "glslang ${name}"
    VERBATIM)
endfunction()

# Plain shaders: shaders/NAME.EXT -> NAME.EXT.spv.
# Variant shaders (VARIANTS src... with MASKS n...): NAME.EXT.<mask>.spv compiled with
# -DVARIANT_MASK=<mask>, for interfaces that change with a case (G-buffer outputs).
function(taa_add_shaders target)
  cmake_parse_arguments(ARG "" "" "PLAIN;VARIANTS;MASKS" ${ARGN})
  set(outputs "")
  foreach(src IN LISTS ARG_PLAIN)
    get_filename_component(name ${src} NAME)
    set(out ${TAA_SHADER_OUT}/${name}.spv)
    taa_compile_shader(${src} ${out} "")
    list(APPEND outputs ${out})
  endforeach()
  foreach(src IN LISTS ARG_VARIANTS)
    get_filename_component(name ${src} NAME)
    foreach(mask IN LISTS ARG_MASKS)
      set(out ${TAA_SHADER_OUT}/${name}.${mask}.spv)
      taa_compile_shader(${src} ${out} "-DVARIANT_MASK=${mask}")
      list(APPEND outputs ${out})
    endforeach()
  endforeach()
  add_custom_target(${target} ALL DEPENDS ${outputs})
endfunction()
