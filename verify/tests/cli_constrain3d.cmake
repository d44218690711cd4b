# CTest tests of `dtlab constrain` on 3D input (closed surfaces in OFF, STL, TetGen .poly and
# .smesh and Medit .mesh; every_format runs every method on each of them; polygon_facets on
# quadrilaterals and a facet with a hole): the mesh verifies with its references; open,
# self-intersecting, duplicated and degenerate surfaces, non-planar and non-simple facets and bad
# option values are refused naming their items. Each case runs cli/constrain3d_check.cmake in a scratch
# directory of its own.
if(NOT TARGET dtlab_cli)
  return()
endif()

foreach(_dtlab_case cube_off two_boxes_smesh schonhardt open_surface self_intersecting duplicate_vertices
                    degenerate_face unknown_method nested_cavity options_of_the_other_dimension steiner_limit
                    every_format polygon_facets nonplanar_quad self_touching_polygon merge_coplanar
                    bad_option_values)
  add_test(NAME cli_constrain3d_${_dtlab_case}
           COMMAND ${CMAKE_COMMAND} -DDTLAB=$<TARGET_FILE:dtlab_cli>
                   -DWORK=${PROJECT_BINARY_DIR}/cli-constrain3d-test/${_dtlab_case} -DCASE=${_dtlab_case}
                   -P ${CMAKE_CURRENT_LIST_DIR}/cli/constrain3d_check.cmake)
  set_tests_properties(cli_constrain3d_${_dtlab_case} PROPERTIES TIMEOUT 300)
endforeach()
