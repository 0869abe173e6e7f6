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

# Every option of the device sections of the option table, through the executable: the
# same bytes on both devices and a change versus the default (tests/app/device_options/).
add_executable(device_options_tests ${CMAKE_CURRENT_LIST_DIR}/device_options_test.cpp)
target_link_libraries(device_options_tests PRIVATE rttest GTest::gtest_main)
target_compile_definitions(device_options_tests
                           PRIVATE RT_DEVICE_OPTION_SCENES="${CMAKE_CURRENT_LIST_DIR}/device_options")
gtest_discover_tests(device_options_tests DISCOVERY_TIMEOUT 60 PROPERTIES LABELS device_options)
