# The distributed driver under mpirun (included from tests/CMakeLists.txt;
# tests/distributed/mpi_render_test.sh): byte-identical images for 2 and 3 ranks on both
# devices, a killed and a failing rank, resuming. Skipped, with the reason, in a build
# without MPI. The faults are injected by raytracer_mpi_faults, the raytracer built with the
# RT_MPI_FAULT hook (src/distributed/mpi_render.cpp), which the raytracer itself does not have.
if(RT_MPI_FOUND)
  add_executable(raytracer_mpi_faults ${PROJECT_SOURCE_DIR}/src/app/main.cpp ${RT_DISTRIBUTED_SOURCES})
  target_compile_definitions(raytracer_mpi_faults PRIVATE RT_WITH_MPI RT_MPI_FAULT_INJECTION)
  target_link_libraries(raytracer_mpi_faults PRIVATE rtcore MPI::MPI_CXX)
endif()
foreach(case multicam large fault)
  foreach(device cpu cl)
    if(case STREQUAL "fault" AND device STREQUAL "cl")
      continue()  # The fault handling does not depend on the device.
    endif()
    set(name mpi.${case}.${device})
    if(RT_MPI_FOUND)
      add_test(NAME ${name}
               COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/distributed/mpi_render_test.sh
                       $<TARGET_FILE:raytracer> ${MPIEXEC_EXECUTABLE} ${RT_SHARED_SCENES_DIR}
                       ${CMAKE_CURRENT_BINARY_DIR}/mpi_${case}_${device} ${device} ${case}
                       $<TARGET_FILE:raytracer_mpi_faults>)
    else()
      add_test(NAME ${name} COMMAND sh -c
               "echo 'SKIP: built without MPI (install libopenmpi-dev and reconfigure)'; exit 77")
    endif()
    set_tests_properties(${name} PROPERTIES LABELS mpi SKIP_RETURN_CODE 77 TIMEOUT 300)
  endforeach()
endforeach()
