# -DTAA_CHECK_HEADERS=ON: every header of ours is compiled alone, in a translation unit that
# holds nothing else, so a header that leans on what its includer happened to include first
# fails to build. Unity batches hide that (a batch neighbour supplies the include), and
# compiling every source file by file to expose it cost CI about four minutes; a header alone
# costs a fraction of a second. With the option on, the check is part of the default build
# (CI turns it on in its one GCC tree); `cmake --build B --target taa_header_check` builds only it.
option(TAA_CHECK_HEADERS "Compile each header alone (target taa_header_check, part of all)" OFF)
if(TAA_CHECK_HEADERS)
  add_custom_target(taa_header_check ALL)
  find_package(Python3 REQUIRED COMPONENTS Interpreter)
  set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${CMAKE_SOURCE_DIR}/cmake/header_pch_menu.py)
endif()

# taa_check_headers(NAME DIRS dir... LIKE target [LIBS lib...]): the headers under each DIR
# (relative to the source root, recursive) compiled as the sources of LIKE are: its include
# folders and definitions, with the usage requirements of LIBS (what LIKE links). Generated
# units live in the build folder; nothing is written to the tree.
#
# Most of a header's CPU alone is the standard, third-party and shared headers of ours it
# includes, parsed again for each header. cmake/header_pch_menu.py picks a few precompiled
# headers of them, priced for the compiler (clang loads one for far less than GCC does),
# each given only to headers that include all of its names themselves, so the check stays
# exact (the script says why); each PCH's units are one object library.
function(taa_check_headers name)
  if(NOT TAA_CHECK_HEADERS)
    return()
  endif()
  cmake_parse_arguments(PARSE_ARGV 1 arg "" "LIKE" "DIRS;LIBS")
  set(checked)
  foreach(dir IN LISTS arg_DIRS)
    file(GLOB_RECURSE headers CONFIGURE_DEPENDS ${CMAKE_SOURCE_DIR}/${dir}/*.h)
    # The PCH choice reads each header's includes: an edit to one configures again.
    set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${headers})
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
      set(unit_of_${header} ${unit})
      list(APPEND checked ${header})
    endforeach()
  endforeach()
  if(NOT checked)
    return()
  endif()
  execute_process(
    COMMAND ${Python3_EXECUTABLE} ${CMAKE_SOURCE_DIR}/cmake/header_pch_menu.py --root ${CMAKE_SOURCE_DIR}
            --compiler ${CMAKE_CXX_COMPILER} --compiler-id ${CMAKE_CXX_COMPILER_ID} --flag=-std=c++${CMAKE_CXX_STANDARD}
            --cache ${CMAKE_BINARY_DIR}/header_check/pch_weights.json ${checked}
    OUTPUT_VARIABLE menu ERROR_VARIABLE menu_error RESULT_VARIABLE menu_status)
  if(NOT menu_status EQUAL 0)
    message(FATAL_ERROR "cmake/header_pch_menu.py failed for ${name} (${menu_status}):\n${menu_error}")
  endif()
  string(REGEX MATCHALL "[^\n]+" lines "${menu}")
  set(index 0)
  foreach(line IN LISTS lines)
    string(FIND "${line}" "|" bar)
    string(SUBSTRING "${line}" 0 ${bar} names)
    math(EXPR after "${bar} + 1")
    string(SUBSTRING "${line}" ${after} -1 members)
    string(REPLACE "," ";" members "${members}")
    set(units)
    foreach(header IN LISTS members)
      list(APPEND units ${unit_of_${header}})
    endforeach()
    if(NOT units)
      continue()
    endif()
    set(target ${name}_headers${index})
    math(EXPR index "${index} + 1")
    add_library(${target} OBJECT EXCLUDE_FROM_ALL ${units})
    set_target_properties(${target} PROPERTIES UNITY_BUILD OFF)
    target_link_libraries(${target} PRIVATE ${arg_LIBS} taa_warnings)
    target_include_directories(${target} PRIVATE $<TARGET_PROPERTY:${arg_LIKE},INCLUDE_DIRECTORIES>)
    target_compile_definitions(${target} PRIVATE $<TARGET_PROPERTY:${arg_LIKE},COMPILE_DEFINITIONS>)
    # Parsing is the check; no code generation is needed (the units define nothing).
    target_compile_options(${target} PRIVATE -O0 -g0)
    if(names)
      # Angled names as written; our own headers come as absolute paths.
      string(REPLACE "," ";" names "${names}")
      list(TRANSFORM names REPLACE "^([^/].*)$" "<\\1>")
      target_precompile_headers(${target} PRIVATE ${names})
    endif()
    add_dependencies(taa_header_check ${target})
  endforeach()
endfunction()
