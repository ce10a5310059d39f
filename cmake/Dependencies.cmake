# Every dependency comes from Debian's packages; ci/install-deps.sh lists them.
find_package(Vulkan REQUIRED)
find_package(glm REQUIRED)
find_package(nlohmann_json REQUIRED)
find_package(TinyGLTF REQUIRED)
# PNG and OpenEXR files are read and written with libpng and OpenEXR directly: OpenImageIO's
# Debian build loads 261 shared libraries at every process start (docs/performance.md).
find_package(PNG REQUIRED)
find_package(OpenEXR CONFIG REQUIRED)
# meshoptimizer's CMake package puts a MESHOPTIMIZER_API definition on every dependant's
# compile line; only gltf_meshopt.cpp and its test include the header, so link the file.
find_library(MESHOPTIMIZER_LIBRARY meshoptimizer REQUIRED)
find_path(MESHOPTIMIZER_INCLUDE_DIR meshoptimizer.h REQUIRED)
# glTF KHR_draco_mesh_compression decoding (and encoding in its tests).
find_package(draco REQUIRED)
find_program(GLSLANG_VALIDATOR glslangValidator REQUIRED)
# glslang as a library: a user's resolve (taa.shader) is compiled at run time.
find_package(Threads REQUIRED)
find_package(glslang CONFIG REQUIRED)
# SPIRV-Tools' optimizer (a dependency of glslang's package): `taa-harness coverage`
# specializes the resolve per case to see which of its lines run.
find_package(SPIRV-Tools-opt CONFIG REQUIRED)

# OpenImageIO only in the tests, as an independent reader of the files the harness writes.
if(TAA_BUILD_TESTS)
  find_package(OpenImageIO REQUIRED)
endif()

# Debian's OpenImageIO 2.4.7 exports /usr/include/opencv4 as an include directory
# although the package does not depend on OpenCV; CMake refuses to generate with a
# missing include path, so drop every entry that does not exist.
foreach(prop INTERFACE_INCLUDE_DIRECTORIES INTERFACE_SYSTEM_INCLUDE_DIRECTORIES)
  if(NOT TARGET OpenImageIO::OpenImageIO)
    break()
  endif()
  get_target_property(dirs OpenImageIO::OpenImageIO ${prop})
  if(dirs)
    set(kept "")
    foreach(dir IN LISTS dirs)
      if(EXISTS "${dir}")
        list(APPEND kept "${dir}")
      endif()
    endforeach()
    set_target_properties(OpenImageIO::OpenImageIO PROPERTIES ${prop} "${kept}")
  endif()
endforeach()
