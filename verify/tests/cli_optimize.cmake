# CTest tests of `dtlab optimize`: a mesh made by `dtlab constrain data/square_with_hole.poly` is
# optimized toward a size (its boundary kept, or split with --split-boundary, references kept),
# with its own sizes, and with a .sol metric; bad input (missing file, clockwise triangle,
# non-manifold edge, bad --size, a .sol of the wrong count, a negative 3D tetrahedron, a 2D or 3D
# mesh without elements) fails with a message naming the file and the item, and writes nothing;
# --list-operators lists the rounds' operators (both dimensions, or the mesh's). Each case runs
# cli/optimize_check.cmake in a scratch directory.
if(NOT TARGET dtlab_cli)
  return()
endif()

foreach(_dtlab_case size_keeps_boundary split_boundary own_sizes sol_metric empty_mesh bad_input list_operators element_limit)
  add_test(NAME cli_optimize_${_dtlab_case}
           COMMAND ${CMAKE_COMMAND} -DDTLAB=$<TARGET_FILE:dtlab_cli>
                   -DPOLY=${PROJECT_SOURCE_DIR}/data/square_with_hole.poly
                   -DWORK=${PROJECT_BINARY_DIR}/cli-optimize-test/${_dtlab_case} -DCASE=${_dtlab_case}
                   -P ${CMAKE_CURRENT_LIST_DIR}/cli/optimize_check.cmake)
  set_tests_properties(cli_optimize_${_dtlab_case} PROPERTIES TIMEOUT 120)
endforeach()
