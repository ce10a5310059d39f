cmake_minimum_required(VERSION 3.25)
# Fails when the test binary holds a GoogleTest suite that tests/CMakeLists.txt did not register
# with CTest (its configure-time scan of TEST(...) lines missed it), naming the suite.
# Usage: cmake -DTEST_BINARY=path -DSUITES=a;b;c -P check_suites.cmake
execute_process(COMMAND ${TEST_BINARY} --gtest_list_tests OUTPUT_VARIABLE listing RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "${TEST_BINARY} --gtest_list_tests failed (${rc})")
endif()
string(REPLACE "\n" ";" lines "${listing}")
set(missing)
foreach(line IN LISTS lines)
  # Suite lines start in column 0 and end with '.'; "Prefix/Suite." for parameterized suites.
  if(line MATCHES "^([A-Za-z0-9_]+/)?([A-Za-z0-9_]+)\\.")
    if(NOT CMAKE_MATCH_2 IN_LIST SUITES)
      list(APPEND missing ${CMAKE_MATCH_2})
    endif()
  endif()
endforeach()
if(missing)
  list(REMOVE_DUPLICATES missing)
  message(FATAL_ERROR "GoogleTest suites not registered with CTest: ${missing}; "
                      "tests/CMakeLists.txt finds suites by lines starting TEST(Suite, TEST_F(Suite, "
                      "or TEST_P(Suite, in *_test.cpp: write the macro that way")
endif()
message(STATUS "all GoogleTest suites are registered")
