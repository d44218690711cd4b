# CTest tests of `dtlab constrain` on 3D input (closed triangulated surfaces in OFF, STL, TetGen
# .poly and .smesh and Medit .mesh; every_format runs every method on each of them): the mesh
# verifies with its references, and open, self-intersecting, duplicated and degenerate surfaces
# are refused naming their items. Each case runs cli/constrain3d_check.cmake in a scratch
# directory of its own.
if(NOT TARGET dtlab_cli)
  return()
endif()

foreach(_dtlab_case cube_off two_boxes_smesh schonhardt open_surface self_intersecting duplicate_vertices
                    degenerate_face unknown_method nested_cavity options_of_the_other_dimension steiner_limit
                    every_format)
  add_test(NAME cli_constrain3d_${_dtlab_case}
           COMMAND ${CMAKE_COMMAND} -DDTLAB=$<TARGET_FILE:dtlab_cli>
                   -DWORK=${PROJECT_BINARY_DIR}/cli-constrain3d-test/${_dtlab_case} -DCASE=${_dtlab_case}
                   -P ${CMAKE_CURRENT_LIST_DIR}/cli/constrain3d_check.cmake)
  set_tests_properties(cli_constrain3d_${_dtlab_case} PROPERTIES TIMEOUT 300)
endforeach()
