# The kernel's private arrays sized from the scene (src/device/kernel_config.cpp).
add_executable(kernel_config_tests ${CMAKE_CURRENT_SOURCE_DIR}/device/kernel_config_test.cpp)
target_link_libraries(kernel_config_tests PRIVATE rttest GTest::gtest_main)
gtest_discover_tests(kernel_config_tests DISCOVERY_TIMEOUT 60)
