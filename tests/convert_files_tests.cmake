# rtconvert run as a user runs it (tests/convert_files_test.cpp, label `convert`): textured
# OBJ and glTF models made by the test import, render textured through the raytracer and
# export back with their textures; output == input is refused; dropped features warn; the
# hw6 glTF round trip keeps object lights, renderer settings and tone map; nothing is
# written into the current folder.
if(NOT TARGET rtconvert)
  return()  # Said once by convert_tests.cmake.
endif()
add_executable(convert_files_tests convert_files_test.cpp)
target_link_libraries(convert_files_tests PRIVATE rtconvert_lib GTest::gtest_main)
target_compile_definitions(
  convert_files_tests PRIVATE RTCONVERT_EXE="$<TARGET_FILE:rtconvert>"
                              RAYTRACER_EXE="$<TARGET_FILE:raytracer>"
                              RT_SHARED_SCENES_DIR="${RT_SHARED_SCENES_DIR}")
gtest_discover_tests(convert_files_tests DISCOVERY_TIMEOUT 60 TEST_PREFIX convert.
                     PROPERTIES LABELS convert)
add_executable(convert_wrap_tests convert_wrap_test.cpp)
target_link_libraries(convert_wrap_tests PRIVATE rtconvert_lib GTest::gtest_main)
gtest_discover_tests(convert_wrap_tests DISCOVERY_TIMEOUT 60 TEST_PREFIX convert.
                     PROPERTIES LABELS convert)
add_executable(convert_lights_tests convert_lights_test.cpp)
target_link_libraries(convert_lights_tests PRIVATE rtconvert_lib GTest::gtest_main)
gtest_discover_tests(convert_lights_tests DISCOVERY_TIMEOUT 60 TEST_PREFIX convert.
                     PROPERTIES LABELS convert)
