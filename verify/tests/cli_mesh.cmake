# CTest tests of `dtlab mesh` (2D, issue 22): every size case on the bundled examples passes
# --verify and writes Triangles with region references and Edges with the segments' markers; the
# output is the same bytes on a second run; the metric written with --output-metric measures the
# same in `dtlab quality`; bad input (missing file, open boundary, bad size, a .sol whose count
# does not match, a metric that is not positive definite, conflicting options, an output that
# cannot be written) fails with a message naming the problem, and leaves no output behind. Each case runs cli/mesh_check.cmake in a scratch directory.
if(NOT TARGET dtlab_cli)
  return()
endif()

foreach(_dtlab_case classical uniform size_map metric_linear metric_polar medit_input front deterministic
                    output_metric missing_file open_boundary bad_size count_mismatch not_positive
                    conflicting_options background_alone resample_classical unknown_method unwritable_output
                    options_without_effect keep_boundary no_interior_edge element_limit)
  add_test(NAME cli_mesh_${_dtlab_case}
           COMMAND ${CMAKE_COMMAND} -DDTLAB=$<TARGET_FILE:dtlab_cli> -DDATA=${PROJECT_SOURCE_DIR}/data
                   -DWORK=${PROJECT_BINARY_DIR}/cli-mesh-test/${_dtlab_case} -DCASE=${_dtlab_case}
                   -P ${CMAKE_CURRENT_LIST_DIR}/cli/mesh_check.cmake)
  set_tests_properties(cli_mesh_${_dtlab_case} PROPERTIES TIMEOUT 120)
endforeach()
