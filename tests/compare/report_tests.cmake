# Tests of `compare report`, `compare reference` and `compare summary` (included from
# tests/CMakeLists.txt): unit tests of their parts, the command line on real renders, and
# the report opened in a headless browser (skipped, with the reason, without chromium).

add_executable(compare_report_tests ${CMAKE_CURRENT_LIST_DIR}/report_test.cpp
                                    ${CMAKE_CURRENT_LIST_DIR}/report_reference_test.cpp)
target_link_libraries(compare_report_tests PRIVATE rtcompare GTest::gtest_main)
gtest_discover_tests(compare_report_tests DISCOVERY_TIMEOUT 60 PROPERTIES LABELS compare)

set(rt_report_exes $<TARGET_FILE:raytracer> $<TARGET_FILE:compare>)
add_test(NAME compare.report_cli
         COMMAND bash ${CMAKE_CURRENT_LIST_DIR}/report_cli.sh ${rt_report_exes}
                 ${CMAKE_SOURCE_DIR} ${RT_SHARED_SCENES_DIR} ${CMAKE_CURRENT_BINARY_DIR}/report_cli)
add_test(NAME compare.report_browser
         COMMAND bash ${CMAKE_CURRENT_LIST_DIR}/report_browser.sh ${rt_report_exes}
                 ${CMAKE_SOURCE_DIR} ${CMAKE_CURRENT_BINARY_DIR}/report_browser)
set_tests_properties(compare.report_cli compare.report_browser
                     PROPERTIES LABELS compare SKIP_RETURN_CODE 77)

# `compare reference` on fresh renders of two cheap course scenes at the suite's settings:
# they must pass, as ref.hw1.simple and ref.hw2.simple_transform do (skipped without the
# scenes). tests/compare/report_reference_agree.sh takes any names of course_scenes.txt.
add_test(NAME compare.reference_render
         COMMAND bash ${CMAKE_CURRENT_LIST_DIR}/report_reference_agree.sh ${rt_report_exes}
                 ${CMAKE_SOURCE_DIR} ${RT_SHARED_SCENES_DIR}
                 ${CMAKE_CURRENT_BINARY_DIR}/reference_render hw1.simple hw2.simple_transform)
set_tests_properties(compare.reference_render PROPERTIES LABELS compare SKIP_RETURN_CODE 77)
