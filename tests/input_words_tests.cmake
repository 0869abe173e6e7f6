# Bad input in words, through the executable (tests/cli_input_words_test.cpp), and the
# pieces behind it: the spelling suggestions, the XML diagnosis, the JPEG writer and reader
# (tests/input_words_unit_test.cpp).
add_executable(input_words_tests cli_input_words_test.cpp input_words_unit_test.cpp)
target_link_libraries(input_words_tests PRIVATE rttest GTest::gtest_main)
target_compile_definitions(input_words_tests PRIVATE RT_SHARED_SCENES_DIR="${RT_SHARED_SCENES_DIR}")
gtest_discover_tests(input_words_tests DISCOVERY_TIMEOUT 60)
