# The OpenCL kernel compiled offline for GPUs this machine does not have (AMD gfx90a and
# gfx1100, NVIDIA sm_90 PTX) by Debian's clang-16 and libclc-16, with the host's GPU build
# options, for the feature sets of representative course scenes (read from the raytracer)
# and the all-features kernel, in float and double (tests/gpu/gpu_kernels.py, docs/gpu.md):
# fails on a compile error, a warning at -Wall -Wextra not in tests/gpu/known_warnings.txt, a
# double instruction in a float build, or a register/scratch/frame figure above its ceiling
# in tests/gpu/budgets.txt. Skips, saying why, without clang-16/libclc-16 or the scenes.
find_package(Python3 COMPONENTS Interpreter QUIET)
if(Python3_Interpreter_FOUND)
  add_test(NAME gpu_compile
           COMMAND ${Python3_EXECUTABLE} ${CMAKE_CURRENT_SOURCE_DIR}/gpu/gpu_kernels.py --check
                   --raytracer $<TARGET_FILE:raytracer> --scenes ${RT_SHARED_SCENES_DIR} --jobs 2)
else()
  add_test(NAME gpu_compile COMMAND sh -c "echo 'SKIP: no Python 3 interpreter (install python3)'; exit 77")
endif()
# Two compiles at a time: PROCESSORS keeps a parallel ctest from oversubscribing the cores.
# About 185 CPU-seconds (the all-features kernel's four AMD compiles are a third): ~95 s on
# two idle cores; the timeout leaves room for a machine that others load as well.
set_tests_properties(gpu_compile PROPERTIES LABELS gpu_compile SKIP_RETURN_CODE 77 TIMEOUT 900
                     PROCESSORS 2)
