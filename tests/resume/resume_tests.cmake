# Stopping and continuing renders (tests/resume/): checkpoints, --resume and --skip-existing
# on partial images, through the executable on both devices.
add_executable(resume_tests ${CMAKE_CURRENT_LIST_DIR}/resume_test.cpp
                            ${CMAKE_CURRENT_LIST_DIR}/checkpoint_rows_test.cpp)
target_link_libraries(resume_tests PRIVATE rttest GTest::gtest_main)
gtest_discover_tests(resume_tests DISCOVERY_TIMEOUT 60)

# --resume under mpirun -np 2 (whole images and tiles), skipped without MPI.
foreach(device cpu cl)
  if(RT_MPI_FOUND)
    add_test(NAME mpi.resume.${device}
             COMMAND ${CMAKE_CURRENT_LIST_DIR}/mpi_resume_test.sh $<TARGET_FILE:raytracer>
                     ${MPIEXEC_EXECUTABLE} ${CMAKE_CURRENT_LIST_DIR}/tiny.xml
                     ${CMAKE_CURRENT_BINARY_DIR}/mpi_resume_${device} ${device})
    set_tests_properties(mpi.resume.${device} PROPERTIES SKIP_RETURN_CODE 77 TIMEOUT 300)
  endif()
endforeach()
