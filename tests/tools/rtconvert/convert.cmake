# rtconvert (tools/rtconvert; built only when Assimp is installed), label `convert`: every
# course scene of tests/course/course_scenes.txt exported to glTF and imported back renders
# the same image (tests/tools/rtconvert/convert_roundtrip.sh), an OBJ + MTL import maps its
# materials and lights as README.md's table says, and bad input gets one line and status 1.
if(NOT TARGET rtconvert)
  message(STATUS "convert tests skipped: rtconvert is not built (libassimp-dev missing)")
  return()
endif()
set(rt_convert_done "")
foreach(line IN LISTS rt_course_lines)
  string(REGEX REPLACE "[ \t]+" ";" fields "${line}")
  list(POP_FRONT fields name scene reference criterion)
  # Not hw5's environment lights: rtconvert does not carry them yet.
  if(NOT name MATCHES "^(hw1|hw1_nobfc|hw2|hw3|spring2021|hw4|hw6)\\.|^hw5\\.cube_(point|directional)$")
    continue()
  endif()
  # One test per scene file and camera (the hw1_nobfc lines repeat hw1's files).
  list(FIND fields "--camera" at)
  set(camera 0)
  if(at GREATER -1)
    math(EXPR at "${at} + 1")
    list(GET fields ${at} camera)
  endif()
  if("${scene}:${camera}" IN_LIST rt_convert_done)
    continue()
  endif()
  list(APPEND rt_convert_done "${scene}:${camera}")
  add_test(NAME convert.${name}
           COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/tools/rtconvert/convert_roundtrip.sh
                   $<TARGET_FILE:raytracer> $<TARGET_FILE:rtconvert> $<TARGET_FILE:compare>
                   ${RT_SHARED_SCENES_DIR}/${scene}
                   ${CMAKE_CURRENT_BINARY_DIR}/convert/${name} ${fields})
  set_tests_properties(convert.${name} PROPERTIES LABELS convert SKIP_RETURN_CODE 77)
endforeach()
add_executable(convert_tests tools/rtconvert/convert_test.cpp)
target_link_libraries(convert_tests PRIVATE rtconvert_lib GTest::gtest_main)
gtest_discover_tests(convert_tests DISCOVERY_TIMEOUT 60 TEST_PREFIX convert. PROPERTIES LABELS convert)
add_test(NAME convert.cli COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/tools/rtconvert/convert_cli.sh
                                  $<TARGET_FILE:rtconvert> $<TARGET_FILE:raytracer>
                                  ${CMAKE_CURRENT_BINARY_DIR}/convert/cli)
set_tests_properties(convert.cli PROPERTIES LABELS convert)
