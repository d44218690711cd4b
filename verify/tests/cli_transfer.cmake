# CTest tests of `dtlab transfer`: two meshes of square_with_hole made by `dtlab mesh` at two
# sizes, a linear field written at the coarse one's vertices, transferred exactly to the fine
# one (and back, and conservatively); the same on two tetrahedral meshes of a cube; bad inputs
# (a .sol of the wrong count, a 3D mesh with a 2D one) named.
if(NOT TARGET dtlab_cli)
  return()
endif()

foreach(_dtlab_case linear_exact conservative metric three_d bad_input)
  add_test(NAME cli_transfer_${_dtlab_case}
           COMMAND ${CMAKE_COMMAND} -DDTLAB=$<TARGET_FILE:dtlab_cli> -DDATA=${PROJECT_SOURCE_DIR}/data
                   -DWORK=${PROJECT_BINARY_DIR}/cli-transfer-test/${_dtlab_case} -DCASE=${_dtlab_case}
                   -DFIELD=${CMAKE_CURRENT_LIST_DIR}/cli/transfer_field.py
                   -P ${CMAKE_CURRENT_LIST_DIR}/cli/transfer_check.cmake)
  set_tests_properties(cli_transfer_${_dtlab_case} PROPERTIES TIMEOUT 120)
endforeach()
