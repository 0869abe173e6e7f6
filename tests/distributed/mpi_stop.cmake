# Stopping, checkpointing and resuming under mpirun -np 2 (tests/distributed/mpi_stop_test.sh):
# SIGINT and SIGTERM to rank 0, SIGINT to mpirun, --checkpoint, and the progress of a resumed
# render; on the CPU reference (the stop does not depend on the device), SIGINT on OpenCL too.
# mpi.stop.notice.cpu: the back-face notice under mpirun (a course scene). Skipped in a build
# without MPI.
foreach(case sigint.cpu sigterm.cpu mpirun.cpu checkpoint.cpu progress.cpu sigint.cl notice.cpu)
  string(REPLACE "." ";" _parts ${case})
  list(GET _parts 0 _case)
  list(GET _parts 1 _device)
  set(_scene ${CMAKE_CURRENT_LIST_DIR}/../resume/tiny.xml)
  if(_case STREQUAL "notice")
    set(_scene ${RT_SHARED_SCENES_DIR}/hw3/cornellbox_boxes_dynamic.xml)
  endif()
  if(RT_MPI_FOUND)
    add_test(NAME mpi.stop.${case}
             COMMAND ${CMAKE_CURRENT_LIST_DIR}/mpi_stop_test.sh $<TARGET_FILE:raytracer>
                     ${MPIEXEC_EXECUTABLE} ${_scene}
                     ${CMAKE_CURRENT_BINARY_DIR}/mpi_stop_${_case}_${_device} ${_case} ${_device})
  else()
    add_test(NAME mpi.stop.${case} COMMAND sh -c
             "echo 'SKIP: built without MPI (install libopenmpi-dev and reconfigure)'; exit 77")
  endif()
  set_tests_properties(mpi.stop.${case} PROPERTIES LABELS mpi SKIP_RETURN_CODE 77 TIMEOUT 300)
endforeach()
