# Tests of `compare` (included from tests/CMakeLists.txt): unit tests of its statistics and
# moment files, and the calibration of its verdicts on planted biases. The kernel-vs-reference
# validation of every course scene that uses it is in tests/course/course.cmake.

add_executable(compare_tests compare/stats_test.cpp compare/moments_test.cpp)
target_link_libraries(compare_tests PRIVATE rtcompare GTest::gtest_main)
target_compile_definitions(compare_tests PRIVATE RT_RAYTRACER_EXE="$<TARGET_FILE:raytracer>"
                                                 RT_COMPARE_EXE="$<TARGET_FILE:compare>"
                                                 RT_SOURCE_DIR="${CMAKE_SOURCE_DIR}")
add_dependencies(compare_tests raytracer compare)
gtest_discover_tests(compare_tests DISCOVERY_TIMEOUT 60)

# A small calibration with assertions (the full table: compare/calibrate.sh). 20 trials
# of the example scene at 48x36 and 35 spp (independent samples): the false alarms of each
# A-vs-A row must stay below the count a test at its nominal level reaches with
# probability 1e-4, and the planted light and camera biases must be caught.
add_test(NAME compare.calibration
         COMMAND compare_calibrate ${CMAKE_SOURCE_DIR}/scenes/example.xml --scale 0.1 --spp 35
                 --trials 20 --threads 2 --alpha 0.05 --tiles 1,8 --biases light:1.02,shift:1
                 --false-alarm-risk 1e-4 --expect welch:8:light:1.02:0.9
                 --expect paired:8:light:1.02:0.9 --expect welch:1:shift:1:0.9
                 --expect paired:8:shift:1:0.9)
set_tests_properties(compare.calibration PROPERTIES LABELS compare)
