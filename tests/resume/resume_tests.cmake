# Stopping and continuing renders (tests/resume/): checkpoints, --resume and --skip-existing
# on partial images, through the executable on both devices.
add_executable(resume_tests ${CMAKE_CURRENT_LIST_DIR}/resume_test.cpp)
target_link_libraries(resume_tests PRIVATE rttest GTest::gtest_main)
gtest_discover_tests(resume_tests DISCOVERY_TIMEOUT 60)
