# The scheduler's passes under --checkpoint (tests/integrator/render_scheduler_cap_test.cpp).
add_executable(render_scheduler_cap_tests
               ${CMAKE_CURRENT_SOURCE_DIR}/integrator/render_scheduler_cap_test.cpp)
target_link_libraries(render_scheduler_cap_tests PRIVATE rttest GTest::gtest_main)
gtest_discover_tests(render_scheduler_cap_tests DISCOVERY_TIMEOUT 60)

# --dielectric choose in the path tracer: one ray at glass, the same expectation as split.
add_executable(path_dielectric_choice_tests
               ${CMAKE_CURRENT_SOURCE_DIR}/integrator/path_dielectric_choice_test.cpp)
target_link_libraries(path_dielectric_choice_tests PRIVATE rttest GTest::gtest_main)
gtest_discover_tests(path_dielectric_choice_tests DISCOVERY_TIMEOUT 60)
