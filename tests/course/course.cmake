# The course's scenes (included from tests/CMakeLists.txt): each against its official image
# (label reference), the kernel against the CPU reference on it (label cl_vs_cpu), and the
# path tracer against the path-traced references (label reference).

option(RT_FULL_CL_VS_CPU "Register the full-size kernel-vs-reference tests" OFF)
function(rt_cl_vs_cpu name scene)
  set(script ${CMAKE_CURRENT_SOURCE_DIR}/course/cl_vs_cpu.sh)
  set(work ${CMAKE_CURRENT_BINARY_DIR}/cl_vs_cpu)
  set(exes $<TARGET_FILE:raytracer> $<TARGET_FILE:compare>)
  add_test(NAME cl_vs_cpu.${name}
           COMMAND bash ${script} ${exes} ${RT_SHARED_SCENES_DIR}/${scene} ${work}/${name} quick
                   ${ARGN})
  set_tests_properties(cl_vs_cpu.${name} PROPERTIES LABELS cl_vs_cpu SKIP_RETURN_CODE 77)
  if(RT_FULL_CL_VS_CPU)
    add_test(NAME cl_vs_cpu_full.${name}
             COMMAND bash ${script} ${exes} ${RT_SHARED_SCENES_DIR}/${scene}
                     ${work}_full/${name} full ${ARGN})
    set_tests_properties(cl_vs_cpu_full.${name} PROPERTIES LABELS cl_vs_cpu_full
                                                           SKIP_RETURN_CODE 77)
  endif()
endfunction()

# Reference-image checks against the course's official images (../shared/scenes).
# The default run renders a regular subset of pixels within a sample budget; the
# label `reference_full` (configure with -DRT_FULL_REFERENCE=ON) renders every pixel.
option(RT_FULL_REFERENCE "Register the full-size reference-image tests" OFF)
add_executable(reference_check course/reference_check.cpp)
target_link_libraries(reference_check PRIVATE rtcompare)
set(RT_REFERENCE_BUDGET 2000000 CACHE STRING "Samples per reference test in the default suite")

# CRITERION is hw12 or hw3, optionally with a limit for the exceptions listed in
# tests/course/course_scenes.txt: the share of byte-identical pixels an hw12 image must reach
# (hw12:99.2), or the largest mean bias of an hw3 image (hw3:0.4).
function(rt_reference name scene reference criterion)
  # CRITERION[,double:P] (tests/course/course_scenes.txt): P is the identical share in double.
  string(REPLACE "," ";" parts "${criterion}")
  list(POP_FRONT parts criterion)
  set(precision_args "")
  foreach(part IN LISTS parts)
    if(part MATCHES "^double:([0-9.]+)$")
      list(APPEND precision_args --double-min-identical ${CMAKE_MATCH_1})
    else()
      message(FATAL_ERROR
              "tests/course/course_scenes.txt: ${name}: unknown criterion part ${part}")
    endif()
  endforeach()
  string(REPLACE ":" ";" criterion "${criterion}")
  list(GET criterion 0 kind)
  set(args ${RT_SHARED_SCENES_DIR}/${scene} ${RT_SHARED_SCENES_DIR}/${reference} --criterion ${kind})
  list(LENGTH criterion parts)
  if(parts GREATER 1)
    list(GET criterion 1 limit)
    if(kind STREQUAL "hw3")
      list(APPEND args --max-bias ${limit})
    elseif(kind STREQUAL "block")
      list(APPEND args --max-block-mae ${limit})
    else()
      list(APPEND args --min-identical ${limit})
    endif()
  endif()
  list(APPEND args ${precision_args} ${ARGN})
  add_test(NAME ref.${name} COMMAND reference_check ${args} --budget ${RT_REFERENCE_BUDGET})
  set_tests_properties(ref.${name} PROPERTIES LABELS reference SKIP_RETURN_CODE 77)
  if(RT_FULL_REFERENCE)
    add_test(NAME ref_full.${name} COMMAND reference_check ${args})
    set_tests_properties(ref_full.${name} PROPERTIES LABELS reference_full SKIP_RETURN_CODE 77)
  endif()
  rt_cl_vs_cpu(${name} ${scene} ${ARGN})  # The same scenes, kernel against reference.
endfunction()
# Every course scene whose files are present, with its official image and criterion (the
# list is tests/course/course_scenes.txt; the thresholds are in reference_check.cpp).
file(STRINGS ${CMAKE_CURRENT_SOURCE_DIR}/course/course_scenes.txt rt_course_lines REGEX "^[^#]")
set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS
             ${CMAKE_CURRENT_SOURCE_DIR}/course/course_scenes.txt)
foreach(line IN LISTS rt_course_lines)
  string(REGEX REPLACE "[ \t]+" ";" fields "${line}")
  list(POP_FRONT fields name scene reference criterion)
  rt_reference(${name} ${scene} ${reference} ${criterion} ${fields})
endforeach()

# The path tracer against the course's path-traced references (bench/path_reference.cpp
# --check: no bias at |z| <= 4, the same share of black pixels, block MAE within 1.15 x the
# reference's own noise floor), on a regular subset of 4x4 blocks at the camera's 100 spp:
# one camera without next-event estimation (glass, uniform: splitting at the glass, black
# pixels) and one with it (diffuse, point light and LightMesh sampled).
foreach(case "glass_uniform:cornellbox_jaroslav_path_glass.xml:4"
             "diffuse_next:cornellbox_jaroslav_path_diffuse.xml:0")
  string(REPLACE ":" ";" case "${case}")
  list(GET case 0 name)
  list(GET case 1 scene)
  list(GET case 2 camera)
  add_test(NAME path_ref.${name}
           COMMAND path_reference ${RT_SHARED_SCENES_DIR}/hw6/pathTracing/${scene}
                   ${RT_SHARED_SCENES_DIR}/hw6/reference/pathTracing --camera ${camera}
                   --budget 1e6 --check)
  set_tests_properties(path_ref.${name} PROPERTIES LABELS reference SKIP_RETURN_CODE 77)
endforeach()
