# What the raytracer prints while and after it renders (tests/app/progress_test.sh): the
# live line on a (pseudo-)terminal on both devices, silence with --quiet, the wrote lines
# in logs, the job-wide line under mpirun, and the back-face culling notice.
set(_progress_cases live.cpu live.cl silent mpi notice)
foreach(c ${_progress_cases})
  string(REPLACE "." ";" _parts ${c})
  list(GET _parts 0 _case)
  set(_arg "")
  if(c MATCHES "\\.")
    list(GET _parts 1 _arg)
  endif()
  if(_case STREQUAL "mpi")
    if(RT_MPI_FOUND)
      set(_arg ${MPIEXEC_EXECUTABLE})
    endif()
  endif()
  add_test(NAME progress.${c}
           COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/app/progress_test.sh $<TARGET_FILE:raytracer>
                   ${RT_SHARED_SCENES_DIR} ${CMAKE_CURRENT_BINARY_DIR}/progress_${c} ${_case} ${_arg})
  set_tests_properties(progress.${c} PROPERTIES LABELS progress SKIP_RETURN_CODE 77 TIMEOUT 300)
endforeach()
