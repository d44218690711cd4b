# CTest tests of the `dtlab` command on 3D input (`dtlab delaunay --dim 3`, 3D point files,
# `dtlab verify` on 3D meshes): the --stats JSON line, --verify, the written mesh passing
# `dtlab verify` and a corrupted one failing it, identical bytes from every --algo and every
# --threads, and the messages and exit codes of bad, coplanar and duplicated input. Each case runs
# cli/delaunay3d_check.cmake in a scratch directory of its own.
if(NOT TARGET dtlab_cli)
  return()
endif()

foreach(_dtlab_case stats_json mesh_verifies tetgen_mesh_verifies corrupted_mesh algos_same_bytes threads_same_bytes malformed_line
                    coplanar duplicates bad_options)
  add_test(NAME cli3d_${_dtlab_case}
           COMMAND ${CMAKE_COMMAND} -DDTLAB=$<TARGET_FILE:dtlab_cli>
                   -DWORK=${PROJECT_BINARY_DIR}/cli3d-test/${_dtlab_case} -DCASE=${_dtlab_case}
                   -P ${CMAKE_CURRENT_LIST_DIR}/cli/delaunay3d_check.cmake)
  set_tests_properties(cli3d_${_dtlab_case} PROPERTIES TIMEOUT 300)
endforeach()
