# One custom command per shader: glslangValidator compiles shaders/NAME.EXT to
# ${TAA_SHADER_OUT}/NAME.EXT.spv and is re-run when the shader or any header under
# shaders/ changes. The renderer finds SPIR-V by name at run time.
set(TAA_SHADER_OUT ${CMAKE_BINARY_DIR}/shaders)

# TAA_SPIRV_FROM: another build tree of this source tree, whose SPIR-V this tree copies instead of
# compiling it again. CI's sanitizer tree takes the GCC tree's (69 files, about 33 s of CPU):
# glslang's output does not depend on the C++ compiler. A copy older than its shader or than any
# shader header fails the build, naming the tree to build first.
set(TAA_SPIRV_FROM "" CACHE PATH "Build tree of this source tree whose SPIR-V is copied, not compiled")
if(TAA_SPIRV_FROM)
  set(from_cache ${TAA_SPIRV_FROM}/CMakeCache.txt)
  set(from_home)
  if(EXISTS ${from_cache})
    file(STRINGS ${from_cache} from_home REGEX "^CMAKE_HOME_DIRECTORY:INTERNAL=")
  endif()
  if(NOT from_home STREQUAL "CMAKE_HOME_DIRECTORY:INTERNAL=${CMAKE_SOURCE_DIR}")
    message(FATAL_ERROR "TAA_SPIRV_FROM=${TAA_SPIRV_FROM} is not a build tree of ${CMAKE_SOURCE_DIR} "
                        "(its CMakeCache.txt names another source tree, or it has none); give a tree "
                        "configured from this one, or leave TAA_SPIRV_FROM empty to compile the SPIR-V")
  endif()
endif()

function(taa_compile_shader src out defines)
  file(GLOB_RECURSE headers CONFIGURE_DEPENDS ${CMAKE_SOURCE_DIR}/shaders/*.glsl
       ${CMAKE_SOURCE_DIR}/shaders/*.h)
  get_filename_component(name ${out} NAME)
  if(TAA_SPIRV_FROM)
    add_custom_command(
      OUTPUT ${out}
      COMMAND ${CMAKE_COMMAND} -DFROM=${TAA_SPIRV_FROM}/shaders/${name} -DTO=${out}
              "-DSOURCES=${CMAKE_CURRENT_SOURCE_DIR}/${src};${headers}"
              -P ${CMAKE_SOURCE_DIR}/cmake/copy_spirv.cmake
      DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/${src} ${headers} ${CMAKE_SOURCE_DIR}/cmake/copy_spirv.cmake
      COMMENT "SPIR-V ${name} from ${TAA_SPIRV_FROM}"
      VERBATIM)
    return()
  endif()
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
