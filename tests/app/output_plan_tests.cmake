# The job-wide output plan (src/app/output_plan.h) through the raytracer executable:
# colliding outputs, outputs over inputs, later scene files missing (tests/app/).
add_executable(output_plan_tests ${CMAKE_CURRENT_SOURCE_DIR}/app/output_plan_test.cpp)
target_link_libraries(output_plan_tests PRIVATE rttest GTest::gtest_main)
gtest_discover_tests(output_plan_tests DISCOVERY_TIMEOUT 60)
