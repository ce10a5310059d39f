# -DTAA_CHECK_HEADERS=ON: every header of ours is compiled alone, in a translation unit that
# holds nothing else, so a header that leans on what its includer happened to include first
# fails to build. Unity batches hide that (a batch neighbour supplies the include), and
# compiling every source file by file to expose it cost CI about four minutes; a header alone
# costs a fraction of a second. With the option on, the check is part of the default build
# (CI turns it on in its one GCC tree); `cmake --build B --target taa_header_check` builds only it.
option(TAA_CHECK_HEADERS "Compile each header alone (target taa_header_check, part of all)" OFF)
if(TAA_CHECK_HEADERS)
  add_custom_target(taa_header_check ALL)
endif()

# taa_check_headers(NAME DIRS dir... LIKE target [LIBS lib...]): the headers under each DIR
# (relative to the source root, recursive) compiled as the sources of LIKE are: its include
# folders and definitions, with the usage requirements of LIBS (what LIKE links). Generated
# units live in the build folder; nothing is written to the tree.
function(taa_check_headers name)
  if(NOT TAA_CHECK_HEADERS)
    return()
  endif()
  cmake_parse_arguments(PARSE_ARGV 1 arg "" "LIKE" "DIRS;LIBS")
  set(units)
  foreach(dir IN LISTS arg_DIRS)
    file(GLOB_RECURSE headers CONFIGURE_DEPENDS ${CMAKE_SOURCE_DIR}/${dir}/*.h)
    foreach(header IN LISTS headers)
      # A header without `#pragma once` is a list meant to be expanded inside its includer
      # (invariant_list.h, the resolve-input table): it is checked where it is expanded.
      file(STRINGS ${header} once REGEX "^#pragma once" LIMIT_COUNT 1)
      if(NOT once)
        continue()
      endif()
      file(RELATIVE_PATH rel ${CMAKE_SOURCE_DIR} ${header})
      string(MAKE_C_IDENTIFIER ${rel} id)
      set(unit ${CMAKE_BINARY_DIR}/header_check/${id}.cpp)
      # Written only when it differs, so a reconfigure does not rebuild every unit.
      set(text "#include \"${header}\"\n")
      if(EXISTS ${unit})
        file(READ ${unit} old)
      else()
        set(old "")
      endif()
      if(NOT old STREQUAL text)
        file(WRITE ${unit} "${text}")
      endif()
      list(APPEND units ${unit})
    endforeach()
  endforeach()
  add_library(${name}_headers OBJECT EXCLUDE_FROM_ALL ${units})
  set_target_properties(${name}_headers PROPERTIES UNITY_BUILD OFF)
  target_link_libraries(${name}_headers PRIVATE ${arg_LIBS} taa_warnings)
  target_include_directories(${name}_headers PRIVATE
    $<TARGET_PROPERTY:${arg_LIKE},INCLUDE_DIRECTORIES>)
  target_compile_definitions(${name}_headers PRIVATE
    $<TARGET_PROPERTY:${arg_LIKE},COMPILE_DEFINITIONS>)
  # Parsing is the check; no code generation is needed (the units define nothing).
  target_compile_options(${name}_headers PRIVATE -O0 -g0)
  add_dependencies(taa_header_check ${name}_headers)
endfunction()
