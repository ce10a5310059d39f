cmake_minimum_required(VERSION 3.25)
# One GoogleTest suite as a ctest test: the verdict its shard's process wrote this ctest run
# (tests/unit/run_shard.py), or, without one (`ctest -R Suite`, a shard that crashed), the
# suite run by itself.
# Usage: cmake -DTEST_BINARY=path -DSUITE=Name -DVERDICT=file -DSHARD=unit.shardK -P suite.cmake
if(EXISTS "${VERDICT}")
  file(READ "${VERDICT}" text)
  message("${SUITE}: from ${SHARD}'s process (its log holds the tests' own output)\n${text}")
  if(text MATCHES "^failed")
    message(FATAL_ERROR "${SUITE} failed in ${SHARD}")
  endif()
  return()
endif()
execute_process(COMMAND "${TEST_BINARY}" "--gtest_filter=${SUITE}.*:*/${SUITE}.*" RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "${SUITE} failed (${rc})")
endif()
