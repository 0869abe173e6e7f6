# The Owen-scrambled Sobol sampler (--sampler sobol): its nets, shuffle and integration error,
# and the two devices drawing the same numbers.
add_executable(sobol_tests ${CMAKE_CURRENT_LIST_DIR}/sobol_test.cpp
               ${CMAKE_CURRENT_LIST_DIR}/sobol_devices_test.cpp)
target_link_libraries(sobol_tests PRIVATE rttest GTest::gtest_main)
target_compile_definitions(sobol_tests PRIVATE RT_SHARED_SCENES_DIR="${RT_SHARED_SCENES_DIR}")
gtest_discover_tests(sobol_tests DISCOVERY_TIMEOUT 60)
