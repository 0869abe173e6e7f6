# The fuzz targets' regression inputs for the image readers and rtconvert's import
# (fuzz/regressions/<target>/), replayed by fuzz_replay_tests (tests/fuzz/fuzz_replay_test.cpp);
# the sanitized tree runs the same executable as sanitize.fuzz_replay (fuzz/CMakeLists.txt).
# fuzz/targets.cpp, compiled into unit_tests, writes its scratch files through fuzz/scratch.cpp.
target_sources(unit_tests PRIVATE ${PROJECT_SOURCE_DIR}/fuzz/scratch.cpp)
add_executable(fuzz_replay_tests ${CMAKE_CURRENT_LIST_DIR}/fuzz_replay_test.cpp
               ${PROJECT_SOURCE_DIR}/fuzz/image_targets.cpp ${PROJECT_SOURCE_DIR}/fuzz/scratch.cpp)
target_include_directories(fuzz_replay_tests PRIVATE ${PROJECT_SOURCE_DIR})
target_link_libraries(fuzz_replay_tests PRIVATE rtcore GTest::gtest_main)
target_compile_definitions(fuzz_replay_tests PRIVATE RT_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
if(TARGET rtconvert_lib)
  target_sources(fuzz_replay_tests PRIVATE ${PROJECT_SOURCE_DIR}/fuzz/convert_targets.cpp)
  target_link_libraries(fuzz_replay_tests PRIVATE rtconvert_lib)
  target_compile_definitions(fuzz_replay_tests PRIVATE RT_FUZZ_CONVERT=1)
endif()
gtest_discover_tests(fuzz_replay_tests DISCOVERY_TIMEOUT 60 TEST_PREFIX fuzz_replay.)
