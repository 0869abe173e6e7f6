# rtconvert's tests beyond convert.cmake (label `convert`):
# - convert_files_test.cpp runs rtconvert as a user does: textured OBJ and glTF models made
#   by the test import, render textured through the raytracer and export back with their
#   textures; output == input is refused; dropped features warn; the hw6 glTF round trip
#   keeps object lights, renderer settings and tone map; nothing is written into the
#   current folder;
# - convert_wrap_test.cpp: repeated texture coordinates moved into the course's [0, 1];
# - convert_extras_test.cpp: directional and spot lights through glTF extras and XML bit
#   for bit, out-of-range extras refused;
# - convert_plan_test.cpp: outputs (the file, the meshes and images beside an XML) checked
#   against the inputs and each other before anything is written.
if(NOT TARGET rtconvert)
  return()  # Said once by convert.cmake.
endif()
foreach(name files wrap extras plan)
  add_executable(convert_${name}_tests ${CMAKE_CURRENT_LIST_DIR}/convert_${name}_test.cpp)
  target_link_libraries(convert_${name}_tests PRIVATE rtconvert_lib GTest::gtest_main)
  target_compile_definitions(
    convert_${name}_tests PRIVATE RTCONVERT_EXE="$<TARGET_FILE:rtconvert>"
                                  RAYTRACER_EXE="$<TARGET_FILE:raytracer>"
                                  RT_SHARED_SCENES_DIR="${RT_SHARED_SCENES_DIR}")
  gtest_discover_tests(convert_${name}_tests DISCOVERY_TIMEOUT 60 TEST_PREFIX convert.
                       PROPERTIES LABELS convert)
endforeach()
