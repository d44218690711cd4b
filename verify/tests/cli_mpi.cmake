# CTest tests of `dtlab-mpi` (mpi/, issue 45) under `mpirun --oversubscribe -np N`, N = 1, 2, 3,
# 4 and 7 on the 2-core CI machine: for each generator of the 2D and 3D suites (degenerate ones
# included) the written mesh is byte-identical to `dtlab delaunay -o`'s for every N, and --check
# (rank 0 compares with the sequential call) passes; bad input exits 1 with a named error on every
# rank count, without a hang. As root, OpenMPI needs OMPI_ALLOW_RUN_AS_ROOT(_CONFIRM).
if(NOT TARGET dtlab_mpi OR NOT DTLAB_MPIEXEC)
  return()
endif()

foreach(_dtlab_case 2:uniform 2:grid 2:exact_circle 2:duplicates 2:collinear 3:uniform 3:grid 3:exact_sphere
                    3:duplicates 3:coplanar 3:clustered bad_input)
  string(REPLACE ":" "_" _dtlab_name ${_dtlab_case})
  add_test(NAME cli_mpi_${_dtlab_name}
           COMMAND ${CMAKE_COMMAND} -DDTLAB=$<TARGET_FILE:dtlab_cli> -DDTLAB_MPI=$<TARGET_FILE:dtlab_mpi>
                   -DMPIEXEC=${DTLAB_MPIEXEC} -DWORK=${PROJECT_BINARY_DIR}/cli-mpi-test/${_dtlab_name}
                   -DCASE=${_dtlab_case} -P ${CMAKE_CURRENT_LIST_DIR}/cli/mpi_check.cmake)
  set_tests_properties(cli_mpi_${_dtlab_name} PROPERTIES TIMEOUT 300
                       ENVIRONMENT "OMPI_ALLOW_RUN_AS_ROOT=1;OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1;OMPI_MCA_rmaps_base_oversubscribe=1")
endforeach()
