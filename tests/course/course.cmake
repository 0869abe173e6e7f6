# Every course scene whose files are present, with its official image and criterion (the
# list is tests/course_scenes.txt; the thresholds are in reference_check.cpp).
file(STRINGS ${CMAKE_CURRENT_SOURCE_DIR}/course_scenes.txt rt_course_lines REGEX "^[^#]")
set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS
             ${CMAKE_CURRENT_SOURCE_DIR}/course_scenes.txt)
foreach(line IN LISTS rt_course_lines)
  string(REGEX REPLACE "[ \t]+" ";" fields "${line}")
  list(POP_FRONT fields name scene reference criterion)
  rt_reference(${name} ${scene} ${reference} ${criterion} ${fields})
endforeach()
