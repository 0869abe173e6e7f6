# The path tracer's --path-estimator mis: closed forms, both devices bit for bit, and its
# finite variance (tests/integrator/path_mis_*.cpp).
add_executable(path_mis_tests integrator/path_mis_test.cpp integrator/path_mis_devices_test.cpp)
target_link_libraries(path_mis_tests PRIVATE rttest GTest::gtest_main)
gtest_discover_tests(path_mis_tests DISCOVERY_TIMEOUT 60)
