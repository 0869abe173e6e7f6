# bench/cycles_anchor.sh against Blender Cycles at 64 x 64 (label `bench`, about half a
# minute; registered with -DRT_BENCH_TESTS=ON, skipped without Blender or the course's scenes).
option(RT_BENCH_TESTS "Register the benchmark smoke tests (Blender Cycles)" OFF)
if(RT_BENCH_TESTS)
  add_test(NAME bench.cycles_anchor
           COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/bench/cycles_anchor_test.sh ${PROJECT_SOURCE_DIR}
                   ${CMAKE_BINARY_DIR} ${RT_SHARED_SCENES_DIR}
                   ${CMAKE_CURRENT_BINARY_DIR}/cycles_anchor_test)
  set_tests_properties(bench.cycles_anchor PROPERTIES LABELS bench SKIP_RETURN_CODE 77 TIMEOUT 600)
endif()
