# CTest tests of the `dtlab` command on 2D input (`dtlab delaunay`, `dtlab verify`): version,
# the --stats JSON line, the written mesh passing `dtlab verify`, identical bytes from every
# --algo, Triangle .node/.ele output, the messages and exit codes of bad, collinear and
# duplicated input, and numeric options out of range refused by name. Each case runs
# cli/delaunay2d_check.cmake in a scratch directory of its own.
if(NOT TARGET dtlab_cli)
  return()
endif()

add_test(NAME cli2d_version COMMAND dtlab_cli --version)
string(REPLACE "." "\\." _dtlab_version_regex "${PROJECT_VERSION}")
set_tests_properties(cli2d_version PROPERTIES PASS_REGULAR_EXPRESSION "^dtlab ${_dtlab_version_regex} ")

foreach(_dtlab_case stats_json mesh_verifies algos_same_bytes ele_output missing_file malformed_line
                    nan_coordinate out_of_range unknown_algo unknown_distribution collinear duplicates
                    bad_option_values)
  add_test(NAME cli2d_${_dtlab_case}
           COMMAND ${CMAKE_COMMAND} -DDTLAB=$<TARGET_FILE:dtlab_cli>
                   -DDEFAULT_INPUT=${PROJECT_SOURCE_DIR}/data/default.node
                   -DWORK=${PROJECT_BINARY_DIR}/cli2d-test/${_dtlab_case} -DCASE=${_dtlab_case}
                   -P ${CMAKE_CURRENT_LIST_DIR}/cli/delaunay2d_check.cmake)
  set_tests_properties(cli2d_${_dtlab_case} PROPERTIES TIMEOUT 300)
endforeach()
