# One custom command per shader: glslangValidator compiles shaders/NAME.EXT to
# ${TAA_SHADER_OUT}/NAME.EXT.spv and is re-run when the shader or any header under
# shaders/ changes. The renderer finds SPIR-V by name at run time.
set(TAA_SHADER_OUT ${CMAKE_BINARY_DIR}/shaders)

function(taa_add_shaders target)
  file(GLOB_RECURSE headers CONFIGURE_DEPENDS ${CMAKE_SOURCE_DIR}/shaders/*.glsl
       ${CMAKE_SOURCE_DIR}/shaders/*.h)
  set(outputs "")
  foreach(src IN LISTS ARGN)
    get_filename_component(name ${src} NAME)
    set(out ${TAA_SHADER_OUT}/${name}.spv)
    # vulkan1.2 target: vulkan1.3 would emit LocalSizeId, which needs maintenance4.
    add_custom_command(
      OUTPUT ${out}
      COMMAND ${CMAKE_COMMAND} -E make_directory ${TAA_SHADER_OUT}
      COMMAND ${GLSLANG_VALIDATOR} --quiet --target-env vulkan1.2 -I${CMAKE_SOURCE_DIR}/shaders
              -o ${out} ${CMAKE_CURRENT_SOURCE_DIR}/${src}
      DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/${src} ${headers}
      COMMENT "glslang ${name}"
      VERBATIM)
    list(APPEND outputs ${out})
  endforeach()
  add_custom_target(${target} ALL DEPENDS ${outputs})
endfunction()
