cmake_minimum_required(VERSION 3.25)
# One SPIR-V file from the build tree TAA_SPIRV_FROM names (cmake/Shaders.cmake), refused when
# it is missing or older than its shader or any shader header: that tree has not compiled the
# shaders as they are now.
# Usage: cmake -DFROM=file -DTO=file -DSOURCES=shader;headers... -P copy_spirv.cmake
if(NOT EXISTS "${FROM}")
  message(FATAL_ERROR "${FROM} is missing: build the shaders of the tree TAA_SPIRV_FROM names first "
                      "(ninja -C TREE taa_shaders), or configure this tree without TAA_SPIRV_FROM")
endif()
foreach(src IN LISTS SOURCES)
  # Also true for equal times: the copy must be strictly newer than each of its sources.
  if("${src}" IS_NEWER_THAN "${FROM}")
    message(FATAL_ERROR "${FROM} is older than ${src}: build the shaders of the tree TAA_SPIRV_FROM "
                        "names first (ninja -C TREE taa_shaders), or configure this tree without it")
  endif()
endforeach()
get_filename_component(dir "${TO}" DIRECTORY)
file(MAKE_DIRECTORY "${dir}")
file(COPY_FILE "${FROM}" "${TO}")
