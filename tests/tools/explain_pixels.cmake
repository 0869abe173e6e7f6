# tools/explain_ensemble.py and tools/explain_pixels.py (docs/course_pixel_residue.md):
# their arithmetic on synthetic inputs, and hw1 spheres' differing pixels in a crop each
# attained by a member of a rounding-sized ensemble. Python 3's standard library only;
# without an interpreter both skip and say why.
find_package(Python3 COMPONENTS Interpreter QUIET)
set(rt_explain ${CMAKE_CURRENT_SOURCE_DIR}/tools/explain_pixels_test.py)
if(Python3_Interpreter_FOUND)
  add_test(NAME explain_pixels.synthetic COMMAND ${Python3_EXECUTABLE} ${rt_explain} synthetic)
  add_test(NAME explain_pixels.spheres_crop
           COMMAND ${Python3_EXECUTABLE} ${rt_explain} crop $<TARGET_FILE:raytracer>
                   ${RT_SHARED_SCENES_DIR} ${CMAKE_CURRENT_BINARY_DIR}/explain_spheres)
  add_test(NAME explain_pixels.spheres_mirror_model
           COMMAND ${Python3_EXECUTABLE} ${rt_explain} model_pixel ${RT_SHARED_SCENES_DIR})
else()
  foreach(name synthetic spheres_crop spheres_mirror_model)
    add_test(NAME explain_pixels.${name} COMMAND sh -c
             "echo 'SKIP: no Python 3 interpreter (install python3)'; exit 77")
  endforeach()
endif()
set_tests_properties(explain_pixels.synthetic explain_pixels.spheres_crop
                     explain_pixels.spheres_mirror_model PROPERTIES
                     SKIP_RETURN_CODE 77 TIMEOUT 120)
