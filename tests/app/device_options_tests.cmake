# The scheduler's passes under --checkpoint (tests/integrator/render_scheduler_cap_test.cpp).
add_executable(render_scheduler_cap_tests
               ${CMAKE_CURRENT_SOURCE_DIR}/integrator/render_scheduler_cap_test.cpp)
target_link_libraries(render_scheduler_cap_tests PRIVATE rttest GTest::gtest_main)
gtest_discover_tests(render_scheduler_cap_tests DISCOVERY_TIMEOUT 60)
