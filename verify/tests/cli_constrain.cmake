# CTest tests of `dtlab constrain` (issue 7): every method on data/square_with_hole.poly passes
# --verify and writes Medit Edges with the segments' markers and Triangles with the region
# attributes; a Medit .mesh with Edges is read as the same graph; crossing segments get a Steiner
# point and still verify; bad input (missing file, malformed line, zero-length segment,
# out-of-range endpoint, unknown method) fails with a message naming the file and the line or
# segment, numbered as the file numbers them. Each case runs cli/constrain_check.cmake in a
# scratch directory of its own.
if(NOT TARGET dtlab_cli)
  return()
endif()

foreach(_dtlab_case methods_verify medit_input crossings missing_file malformed_line zero_length out_of_range
                    unknown_method)
  add_test(NAME cli_constrain_${_dtlab_case}
           COMMAND ${CMAKE_COMMAND} -DDTLAB=$<TARGET_FILE:dtlab_cli>
                   -DPOLY=${PROJECT_SOURCE_DIR}/data/square_with_hole.poly
                   -DWORK=${PROJECT_BINARY_DIR}/cli-constrain-test/${_dtlab_case} -DCASE=${_dtlab_case}
                   -P ${CMAKE_CURRENT_LIST_DIR}/cli/constrain_check.cmake)
  set_tests_properties(cli_constrain_${_dtlab_case} PROPERTIES TIMEOUT 120)
endforeach()
