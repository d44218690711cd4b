# CTest tests of `dtlab mesh` for volumes (issue 17): closed surfaces (OFF, STL) meshed in the
# classical case, with a uniform size, a size map and an anisotropic metric on a background mesh,
# each passing --verify with Tetrahedra and boundary Triangles written; the output is the same
# bytes on a second run; bad input (an open surface, a .sol whose count does not match, a size map
# without a background, the front method, an unknown --optimize effort, a surface without facets)
# fails with a message naming the problem, and writes nothing; the three efforts run (light: one round); polygonal
# facets (issue 19: a .poly facet with a hole, OFF quads) mesh with their markers, and a non-planar
# quad, a bow tie and a self-touching facet are refused by name. Each case runs
# cli/mesh3d_check.cmake in a scratch directory.
if(NOT TARGET dtlab_cli)
  return()
endif()

foreach(_dtlab_case classical uniform stl size_map metric deterministic open_surface empty_surface count_mismatch
                    no_background front polygonal_facets bad_facets effort no_interior_edge element_limit)
  add_test(NAME cli_mesh3d_${_dtlab_case}
           COMMAND ${CMAKE_COMMAND} -DDTLAB=$<TARGET_FILE:dtlab_cli> -DDATA=${PROJECT_SOURCE_DIR}/data
                   -DWORK=${PROJECT_BINARY_DIR}/cli-mesh3d-test/${_dtlab_case} -DCASE=${_dtlab_case}
                   -P ${CMAKE_CURRENT_LIST_DIR}/cli/mesh3d_check.cmake)
  set_tests_properties(cli_mesh3d_${_dtlab_case} PROPERTIES TIMEOUT 120)
endforeach()
