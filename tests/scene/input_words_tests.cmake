# Bad input in words, through the executable (tests/scene/input_words_cli_test.cpp), and the
# pieces behind it: the spelling suggestions, the XML diagnosis, the JPEG writer and reader
# (tests/scene/input_words_test.cpp).
add_executable(input_words_tests ${CMAKE_CURRENT_LIST_DIR}/input_words_cli_test.cpp
                                 ${CMAKE_CURRENT_LIST_DIR}/input_words_test.cpp)
target_link_libraries(input_words_tests PRIVATE rttest GTest::gtest_main)
target_compile_definitions(input_words_tests PRIVATE RT_SHARED_SCENES_DIR="${RT_SHARED_SCENES_DIR}")
gtest_discover_tests(input_words_tests DISCOVERY_TIMEOUT 60)
